// validation scene pv3204 (seed 3204)
#version 3.7;
#declare NS = 1;
#declare NLT = 241;
#declare LINES = array[241] { 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214, 215, 216, 217, 218, 219, 220, 221, 222, 223, 224, 225, 226, 227, 228, 229, 230, 231, 232, 233, 234, 235, 236, 237, 238, 239, 240, 241, 242, 243, 244, 245, 246, 247, 248, 249, 250, 251, 252, 253, 254, 255, 256, 257, 258, 259, 260, 261, 262, 263, 264, 265, 266, 267, 268, 269, 270, 271, 272, 273, 274, 275, 276, 277, 278, 279, 280, 281, 282, 283, 284, 285, 286, 287, 288, 289, 290, 291, 292, 293, 294, 295, 296, 297, 298, 299, 300, 301, 302, 303, 304, 305, 306, 307, 308, 309, 310 };
#declare LR = 114071.76381256491;  // line rate, Hz
#declare TAU = 8.427787599509442e-06;  // exposure, s
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
// film: 620 x 4 samples spanning y/z in [0.2153658895, 0.3102181134] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 429.4338976, 1634.120884>
  right <0, 155, 0>
  up <1, 0, 0>
  aperture 32.170987 blur_samples 19 focal_point <0, 526.6984888, 2004.2409> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 14727.123
  pigment { function { max(0.002, min(0.98, 0.166002 * (1 + -0.199634 * ((y / 14727.123) - 0.2627920015) / 0.04742611197 + 0.122818 * sin(8.5640616 * ((y / 14727.123) - 0.2627920015) / 0.04742611197 + 4.93845)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 587.7238059, 2740.831442> + 82224.9 * <-0.1320155219, 0.3818549232, -0.9147451665> color rgb FL }
light_source { <0, 587.7238059, 2740.831442> + 82224.9 * <-0.6501564724, 0.7593101566, 0.02728822916> color rgb FL * 0.3255 }


// ball 0: pingpong
#declare C0_0 = <0, 587.7238059, 2740.831442>;  // mm
#declare V_0 = <20116.10492, 1178.960941, 2885.720843>;  // mm/s
#declare TC_0 = 0.0016656181481702632;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.8871593766, 0.3992217195, 0.04435796883> }
  finish { ambient 0.5831 diffuse 0.4169 phong 0.3 phong_size 40 } }
  no_shadow
  rotate <332.5279715, 287.1439108, 181.07197>
  transform { Axis_Rotate_Trans(<-0.1025926008, 0.8176837967, -0.5664520869>, 10736.599 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
