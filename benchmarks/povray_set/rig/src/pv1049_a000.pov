// validation scene pv1049_a000 (seed 1049)
#version 3.7;
#declare NS = 1;
#declare NLT = 109;
#declare LINES = array[109] { 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138 };
#declare LR = 3351.2046280514132;  // line rate, Hz
#declare TAU = 0.0001398059389709826;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.344904 * sin(628.3185307 * T + 0.150432));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 2400 x 4 samples spanning y/z in [-0.2909606191, -0.2645054325] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -1480.853068, 5331.930058>
  right <0, 141.0572043, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 29263.213
  pigment { function { max(0.002, min(0.98, 0.0120004 * (1 + -0.318539 * ((y / 29263.213) - -0.2777330258) / 0.01322759327 + 0 * sin(16.59939 * ((y / 29263.213) - -0.2777330258) / 0.01322759327 + 4.31965)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -2961.686514, 10829.4944> + 324885 * <0.4634427409, -0.453449096, -0.7613177676> color rgb FL }


// ball 0: golf
#declare C0_0 = <0, -2961.686514, 10829.4944>;  // mm
#declare V_0 = <1446.837261, -219.0114778, -306.6276569>;  // mm/s
#declare TC_0 = 0.025065613510101448;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.775630337, 0.775630337, 0.775630337> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.1896 diffuse 0.8104 phong 0.35 phong_size 40 } }
  no_shadow
  rotate <300.7042394, 62.44342707, 212.9750103>
  transform { Axis_Rotate_Trans(<0.3772716169, -0.7938345596, -0.4769620729>, 0 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
