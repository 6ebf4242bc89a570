// validation scene pv3804 (seed 3804)
#version 3.7;
#declare NS = 1;
#declare NLT = 247;
#declare LINES = array[247] { 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214, 215, 216, 217, 218, 219, 220, 221, 222, 223, 224, 225, 226, 227, 228, 229, 230, 231, 232, 233, 234, 235, 236, 237, 238, 239, 240, 241, 242, 243, 244, 245, 246, 247, 248, 249, 250, 251, 252, 253, 254, 255, 256, 257, 258, 259, 260, 261, 262, 263, 264, 265, 266, 267, 268, 269, 270, 271, 272, 273, 274, 275, 276, 277, 278, 279, 280, 281, 282, 283, 284, 285, 286, 287, 288, 289, 290, 291, 292, 293, 294, 295, 296, 297, 298, 299, 300, 301, 302, 303, 304, 305, 306, 307, 308, 309, 310, 311, 312, 313, 314, 315, 316, 317, 318 };
#declare LR = 13035.842431849851;  // line rate, Hz
#declare TAU = 5.398530253069029e-06;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.335578 * sin(628.3185307 * T + 4.61975));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 744 x 4 samples spanning y/z in [0.07591165233, 0.1115408014] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 490.8074156, 5236.606999>
  right <0, 186.5758515, 0>
  up <1, 0, 0>
  aperture 17.247291 blur_samples 19 focal_point <0, 718.5689774, 7666.6799> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 39616.915
  pigment { function { max(0.002, min(0.98, 0.468629 * (1 + -0.141322 * ((y / 39616.915) - 0.09372622688) / 0.01781457455 + 0.0796252 * sin(7.9015472 * ((y / 39616.915) - 0.09372622688) / 0.01781457455 + 2.04473)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 815.092752, 10608.22217> + 318247 * <-0.6654868217, 0.001464771927, -0.7464081622> color rgb FL }
light_source { <0, 815.092752, 10608.22217> + 318247 * <0.4750400205, -0.6949471654, -0.5398012748> color rgb FL * 0.2068 }


// ball 0: golf
#declare C0_0 = <0, 815.092752, 10608.22217>;  // mm
#declare V_0 = <-2395.279678, -126.207802, -54.14455998>;  // mm/s
#declare TC_0 = 0.014958757059195946;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.2376259655, 0.2376259655, 0.2376259655> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.5338 diffuse 0.4662 phong 0.35 phong_size 40 } }
  no_shadow
  rotate <289.9587258, 103.9173086, 266.2259143>
  transform { Axis_Rotate_Trans(<-0.3147345765, 0.008703826017, 0.9491398157>, 0 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
