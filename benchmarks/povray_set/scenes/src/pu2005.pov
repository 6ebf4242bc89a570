// validation scene pu2005 (seed 2005)
#version 3.7;
#declare NS = 1;
#declare NLT = 185;
#declare LINES = array[185] { 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214, 215, 216, 217, 218, 219, 220, 221, 222, 223, 224, 225, 226, 227, 228, 229, 230, 231, 232, 233, 234, 235, 236, 237 };
#declare LR = 144.43971512737343;  // line rate, Hz
#declare TAU = 0.0006700969635876556;  // exposure, s
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
// film: 1760 x 4 samples spanning y/z in [-0.007975338993, 0.00860107979] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 2.076186919, 6635.932733>
  right <0, 110, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 34359.618
  pigment { function { max(0.002, min(0.98, 0.658279 * (1 + 0.215123 * ((y / 34359.618) - 0.0003128703986) / 0.008288209391 + 0 * sin(7.3533433 * ((y / 34359.618) - 0.0003128703986) / 0.008288209391 + 0.649678)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 49.80212279, 13561.80226> + 406854 * <0.9206130288, 0.3536256386, 0.1655915423> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, 49.80212279, 13561.80226>;  // mm
#declare V_0 = <-55.32650533, 78.21864543, -8.228939182>;  // mm/s
#declare TC_0 = 1.0038790222767504;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.1305305479, 0.1585013796, 0.02797083169> }
  finish { ambient 1 diffuse 0 } }
  no_shadow
  rotate <252.1405814, 123.7377883, 159.2057694>
  transform { Axis_Rotate_Trans(<-0.1360687413, -0.9273713452, -0.3485221453>, 14.530985 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
