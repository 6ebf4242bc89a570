// validation scene pv0177 (seed 177)
#version 3.7;
#declare NS = 3;
#declare NLT = 65;
#declare LINES = array[65] { 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82 };
#declare LR = 896.5388342118657;  // line rate, Hz
#declare TAU = 0.0005298106715907818;  // exposure, s
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
// film: 1440 x 4 samples spanning y/z in [-0.005156963567, 0.004427706414] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -3.42386039, 9389.994666>
  right <0, 90, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 30676.724
  pigment { function { max(0.002, min(0.98, 0.733807 * (1 + -0.219843 * ((y / 30676.724) - -0.0003646285766) / 0.00479233499 + 0.0905465 * sin(11.116829 * ((y / 30676.724) - -0.0003646285766) / 0.00479233499 + 4.97629)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -1.438065792, 5225.004233> + 156750 * <0.2271582789, 0.5350302609, -0.8137209204> color rgb FL }
light_source { <0, -1.438065792, 5225.004233> + 156750 * <0.04487960712, -0.8457671637, 0.5316612885> color rgb FL * 0.5063 }


// ball 0: pingpong
#declare C0_0 = <0, -1.438065792, 5225.004233>;  // mm
#declare V_0 = <591.3704745, 41.51391862, -322.4188215>;  // mm/s
#declare TC_0 = 0.05577003258755018;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.1253298204, 0.1253298204, 0.1253298204> }
  finish { ambient 0.2389 diffuse 0.7611 phong 0.3 phong_size 40 } }
  no_shadow
  rotate <232.5306766, 148.6996936, 7.969544075>
  transform { Axis_Rotate_Trans(<0.7942857635, 0.5984130837, -0.1049376347>, 0 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
