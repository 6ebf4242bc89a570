// validation scene pv0040 (seed 40)
#version 3.7;
#declare NS = 1;
#declare NLT = 245;
#declare LINES = array[245] { 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214, 215, 216, 217, 218, 219, 220, 221, 222, 223, 224, 225, 226, 227, 228, 229, 230, 231, 232, 233, 234, 235, 236, 237, 238, 239, 240, 241, 242, 243, 244, 245, 246, 247, 248, 249, 250, 251, 252, 253, 254, 255, 256, 257, 258, 259, 260, 261, 262, 263, 264, 265, 266, 267, 268, 269, 270, 271, 272, 273, 274, 275, 276, 277, 278, 279, 280, 281, 282, 283, 284, 285, 286, 287, 288, 289, 290, 291, 292, 293, 294, 295, 296, 297, 298, 299, 300, 301, 302, 303, 304, 305, 306, 307, 308, 309, 310, 311, 312, 313, 314, 315 };
#declare LR = 2749.610759682214;  // line rate, Hz
#declare TAU = 3.352844545163163e-05;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.24054 * sin(753.9822369 * T + 0.353194));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 512 x 4 samples spanning y/z in [-0.01654858419, 0.01198183531] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -10.24442047, 4486.526732>
  right <0, 128.0024898, 0>
  up <1, 0, 0>
  aperture 4.5110747 blur_samples 19 focal_point <0, -6.398528773, 2802.2249> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 9471.5738
  pigment { function { max(0.002, min(0.98, 0.689384 * (1 + 0.0755787 * ((y / 9471.5738) - -0.002283374441) / 0.01426520975 + 0.191556 * sin(3.3431177 * ((y / 9471.5738) - -0.002283374441) / 0.01426520975 + 5.8238)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 18.50572932, 4349.497309> + 130485 * <-0.2118199807, 0.1665578763, -0.9630113029> color rgb FL }
light_source { <0, 18.50572932, 4349.497309> + 130485 * <0.6380427955, -0.7663530873, 0.07486211767> color rgb FL * 0.6295 }


// ball 0: pingpong
#declare C0_0 = <0, 18.50572932, 4349.497309>;  // mm
#declare V_0 = <469.1888392, -284.8391913, -302.9917283>;  // mm/s
#declare TC_0 = 0.070191753258307;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.1098138251, 0.1098138251, 0.1098138251> }
  finish { ambient 0.4268 diffuse 0.5732 phong 0.2476 phong_size 40 } }
  no_shadow
  rotate <189.219073, 211.2084611, 87.75992705>
  transform { Axis_Rotate_Trans(<-0.7106229415, -0.3923904253, 0.5839904016>, 0 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
