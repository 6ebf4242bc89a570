// validation scene pv0060 (seed 60)
#version 3.7;
#declare NS = 1;
#declare NLT = 255;
#declare LINES = array[255] { 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214, 215, 216, 217, 218, 219, 220, 221, 222, 223, 224, 225, 226, 227, 228, 229, 230, 231, 232, 233, 234, 235, 236, 237, 238, 239, 240, 241, 242, 243, 244, 245, 246, 247, 248, 249, 250, 251, 252, 253, 254, 255, 256, 257, 258, 259, 260, 261, 262, 263, 264, 265, 266, 267, 268, 269, 270, 271, 272, 273, 274, 275, 276, 277, 278, 279, 280, 281, 282, 283, 284, 285, 286, 287, 288, 289, 290, 291, 292, 293, 294, 295, 296, 297, 298, 299, 300, 301, 302, 303, 304, 305, 306, 307, 308, 309, 310, 311, 312, 313, 314, 315, 316, 317, 318, 319, 320, 321, 322, 323, 324, 325, 326, 327, 328 };
#declare LR = 137936.17427045637;  // line rate, Hz
#declare TAU = 1.5756317748720639e-06;  // exposure, s
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
// film: 424 x 4 samples spanning y/z in [-0.04984638801, 0.06322653459] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 6.271596705, 937.4481314>
  right <0, 106, 0>
  up <1, 0, 0>
  aperture 38.566871 blur_samples 19 focal_point <0, 27.34902136, 4088.0003> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 27954.206
  pigment { function { max(0.002, min(0.98, 0.469197 * (1 + -0.380614 * ((y / 27954.206) - 0.00669007329) / 0.0565364613 + 0 * sin(12.318381 * ((y / 27954.206) - 0.00669007329) / 0.0565364613 + 2.01642)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 215.0387494, 6045.49881> + 181365 * <0.2977266097, 0.8317287541, -0.4686001979> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, 215.0387494, 6045.49881>;  // mm
#declare V_0 = <-43883.14146, 39244.71332, -5290.126836>;  // mm/s
#declare TC_0 = 0.0014571956998451483;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.07368886118, 0.07205133093, 0.06713874019>] [0.5 rgb <0.07368886118, 0.07205133093, 0.06713874019>] [0.5 rgb <0.06140738432, 0.006550120994, 0.004912590745>] [1.0 rgb <0.06140738432, 0.006550120994, 0.004912590745>] } }
  finish { ambient 0.3743 diffuse 0.6257 phong 0.2143 phong_size 40 } }
  no_shadow
  rotate <241.3220831, 20.90621947, 80.27527007>
  transform { Axis_Rotate_Trans(<0.4043420144, -0.8236567069, -0.3976143414>, 0 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
