// validation scene pu2029 (seed 2029)
#version 3.7;
#declare NS = 1;
#declare NLT = 75;
#declare LINES = array[75] { 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94 };
#declare LR = 4698.115956198212;  // line rate, Hz
#declare TAU = 6.020919370040164e-05;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.0610907 * sin(753.9822369 * T + 1.80304));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 2000 x 4 samples spanning y/z in [-0.06205501049, 0.06653307443] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 2.176554668, 972.0962877>
  right <0, 125, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 40187.096
  pigment { function { max(0.002, min(0.98, 0.740058 * (1 + -0.270477 * ((y / 40187.096) - 0.002239031972) / 0.06429404246 + 0 * sin(24.149549 * ((y / 40187.096) - 0.002239031972) / 0.06429404246 + 3.3354)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -29.24462099, 9916.464514> + 297494 * <0.1781306765, -0.2215028437, -0.9587522893> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, -29.24462099, 9916.464514>;  // mm
#declare V_0 = <5605.278665, -496.4839193, -1458.867044>;  // mm/s
#declare TC_0 = 0.012132523022297916;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.1424459212, 0.1392804563, 0.1297840615> }
  finish { ambient 1 diffuse 0 } }
  no_shadow
  rotate <172.208441, 323.7907951, 319.2885412>
  transform { Axis_Rotate_Trans(<0.8077403435, -0.2745494776, -0.5217069309>, 621.04676 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
