// validation scene pv0112 (seed 112)
#version 3.7;
#declare NS = 1;
#declare NLT = 59;
#declare LINES = array[59] { 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74 };
#declare LR = 4323.076022649429;  // line rate, Hz
#declare TAU = 1.91377778495961e-05;  // exposure, s
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
// film: 2720 x 4 samples spanning y/z in [0.08172403592, 0.1380790024] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 329.9245102, 3002.001362>
  right <0, 169.1776861, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 45291.421
  pigment { function { max(0.002, min(0.98, 0.671141 * (1 + 0.0763063 * ((y / 45291.421) - 0.1099015192) / 0.02817748324 + 0.184894 * sin(3.9868121 * ((y / 45291.421) - 0.1099015192) / 0.02817748324 + 3.43749)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 994.9793993, 8118.387329> + 243552 * <0.2697827409, 0.4742975547, -0.8380090109> color rgb FL }
light_source { <0, 994.9793993, 8118.387329> + 243552 * <0.450978681, -0.8349834957, -0.3153106265> color rgb FL * 0.3811 }


// ball 0: pingpong
#declare C0_0 = <0, 994.9793993, 8118.387329>;  // mm
#declare V_0 = <3339.263463, -23.4203039, -280.4516619>;  // mm/s
#declare TC_0 = 0.010409254837119753;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.1084266315, 0.04879198419, 0.005421331576> }
  finish { ambient 0.3387 diffuse 0.6613 phong 0.3 phong_size 40 } }
  no_shadow
  rotate <287.4702342, 352.2751312, 9.623703543>
  transform { Axis_Rotate_Trans(<0.02906843216, 0.5735559724, 0.8186504583>, 2005.4419 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
