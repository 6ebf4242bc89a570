// validation scene pv0235 (seed 235)
#version 3.7;
#declare NS = 1;
#declare NLT = 101;
#declare LINES = array[101] { 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128 };
#declare LR = 14898.64129937501;  // line rate, Hz
#declare TAU = 6.155651098141398e-05;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.160494 * sin(753.9822369 * T + 2.3987));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 2800 x 4 samples spanning y/z in [-0.04002804733, 0.04887772152] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 8.714480088, 1969.446536>
  right <0, 175.0951585, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 26328.553
  pigment { function { max(0.002, min(0.98, 0.0385591 * (1 + -0.388209 * ((y / 26328.553) - 0.004424837093) / 0.04445288442 + 0 * sin(15.16654 * ((y / 26328.553) - 0.004424837093) / 0.04445288442 + 5.53892)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 63.26045989, 9168.939553> + 275068 * <-0.01087817358, 0.7267131795, -0.6868548756> color rgb FL }


// ball 0: golf
#declare C0_0 = <0, 63.26045989, 9168.939553>;  // mm
#declare V_0 = <7351.26475, 1087.530852, 262.2347154>;  // mm/s
#declare TC_0 = 0.005235376732190476;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.7801753178, 0.7801753178, 0.7801753178> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.4043 diffuse 0.5957 phong 0.35 phong_size 40 } }
  no_shadow
  rotate <191.7612745, 54.7363557, 42.84547143>
  transform { Axis_Rotate_Trans(<0.9908294384, -0.1149584466, 0.0710040815>, 0 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
