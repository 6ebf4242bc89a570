// validation scene pv1009_a090 (seed 1009)
#version 3.7;
#declare NS = 1;
#declare NLT = 65;
#declare LINES = array[65] { 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81 };
#declare LR = 4122.855809354999;  // line rate, Hz
#declare TAU = 5.245483318631635e-05;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = 1;
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 1424 x 4 samples spanning y/z in [-0.03026612217, 0.03661156832] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 4.222220469, 1330.787582>
  right <0, 89, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 4867.5827
  pigment { function { max(0.002, min(0.98, 0.57537 * (1 + 0.059445 * ((y / 4867.5827) - 0.003172723076) / 0.03343884525 + 0.201358 * sin(11.998868 * ((y / 4867.5827) - 0.003172723076) / 0.03343884525 + 2.03104)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -6.960979897, 1524.297679> + 45728.9 * <-0.4365049677, -0.7462344853, 0.5025907939> color rgb FL }


// ball 0: pingpong
#declare C0_0 = <0, -6.960979897, 1524.297679>;  // mm
#declare V_0 = <-2812.196468, -353.8884532, -1727.563234>;  // mm/s
#declare TC_0 = 0.011884965729050276;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.2809271141, 0.2809271141, 0.2809271141> }
  finish { ambient 0.4815 diffuse 0.5185 phong 0.3 phong_size 40 } }
  no_shadow
  rotate <301.7149309, 315.6414506, 214.9592772>
  transform { Axis_Rotate_Trans(<0.8945547755, 0.4097646371, 0.178506851>, 0 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
