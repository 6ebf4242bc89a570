// validation scene pv0293 (seed 293)
#version 3.7;
#declare NS = 1;
#declare NLT = 215;
#declare LINES = array[215] { 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214, 215, 216, 217, 218, 219, 220, 221, 222, 223, 224, 225, 226, 227, 228, 229, 230, 231, 232, 233, 234, 235, 236, 237, 238, 239, 240, 241, 242, 243, 244, 245, 246, 247, 248, 249, 250, 251, 252, 253, 254, 255, 256, 257, 258, 259, 260, 261, 262, 263, 264, 265, 266, 267, 268, 269, 270, 271, 272, 273, 274, 275, 276 };
#declare LR = 1153.1899696432279;  // line rate, Hz
#declare TAU = 0.00039867883916396517;  // exposure, s
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
// film: 3152 x 4 samples spanning y/z in [-0.3000726822, -0.1879985519] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -441.9392911, 1810.962254>
  right <0, 202.9620196, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 5829.8137
  pigment { function { max(0.002, min(0.98, 0.722117 * (1 + -0.181779 * ((y / 5829.8137) - -0.244035617) / 0.05603706515 + 0.0542303 * sin(12.156989 * ((y / 5829.8137) - -0.244035617) / 0.05603706515 + 6.09857)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -269.5602329, 1037.594682> + 31127.8 * <-0.09993174818, -0.04568279571, -0.9939450326> color rgb FL }
light_source { <0, -269.5602329, 1037.594682> + 31127.8 * <0.5732398053, -0.816017071, -0.07424463262> color rgb FL * 0.6201 }


// ball 0: golf
#declare C0_0 = <0, -269.5602329, 1037.594682>;  // mm
#declare V_0 = <-237.2216503, -33.99316259, 26.73028153>;  // mm/s
#declare TC_0 = 0.1465500086271865;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.1519318635, 0.1519318635, 0.1519318635> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.1065 diffuse 0.8935 phong 0.35 phong_size 40 } }
  no_shadow
  rotate <212.6342919, 176.3477562, 28.16165608>
  transform { Axis_Rotate_Trans(<0.3398127925, -0.9397296889, -0.03788638186>, 0 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
