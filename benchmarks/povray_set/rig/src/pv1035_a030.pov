// validation scene pv1035_a030 (seed 1035)
#version 3.7;
#declare NS = 1;
#declare NLT = 61;
#declare LINES = array[61] { 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77 };
#declare LR = 4489.406681209361;  // line rate, Hz
#declare TAU = 4.852373243812323e-05;  // exposure, s
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
// film: 2896 x 4 samples spanning y/z in [-0.07958861896, 0.07964360934] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 0.03125390686, 1136.70456>
  right <0, 181, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 23410.69
  pigment { function { max(0.002, min(0.98, 0.521972 * (1 + -0.303672 * ((y / 23410.69) - 2.749518913e-05) / 0.07961611415 + 0 * sin(18.078477 * ((y / 23410.69) - 2.749518913e-05) / 0.07961611415 + 1.58469)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 281.5092625, 6732.687107> + 201981 * <0.649005538, 0.6684389761, -0.3632920957> color rgb FL }


// ball 0: pingpong
#declare C0_0 = <0, 281.5092625, 6732.687107>;  // mm
#declare V_0 = <3590.485056, -216.2320675, -76.27968533>;  // mm/s
#declare TC_0 = 0.010469089422600292;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.1313704171, 0.05911668768, 0.006568520853> }
  finish { ambient 0.1133 diffuse 0.8867 phong 0.3 phong_size 40 } }
  no_shadow
  rotate <41.48711984, 71.43123676, 13.8395749>
  transform { Axis_Rotate_Trans(<-0.6951743744, -0.3456966553, 0.6302590037>, 1537.4163 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
