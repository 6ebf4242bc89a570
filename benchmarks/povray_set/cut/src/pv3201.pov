// validation scene pv3201 (seed 3201)
#version 3.7;
#declare NS = 1;
#declare NLT = 295;
#declare LINES = array[295] { 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214, 215, 216, 217, 218, 219, 220, 221, 222, 223, 224, 225, 226, 227, 228, 229, 230, 231, 232, 233, 234, 235, 236, 237, 238, 239, 240, 241, 242, 243, 244, 245, 246, 247, 248, 249, 250, 251, 252, 253, 254, 255, 256, 257, 258, 259, 260, 261, 262, 263, 264, 265, 266, 267, 268, 269, 270, 271, 272, 273, 274, 275, 276, 277, 278, 279, 280, 281, 282, 283, 284, 285, 286, 287, 288, 289, 290, 291, 292, 293, 294, 295, 296, 297, 298, 299, 300, 301, 302, 303, 304, 305, 306, 307, 308, 309, 310, 311, 312, 313, 314, 315, 316, 317, 318, 319, 320, 321, 322, 323, 324, 325, 326, 327, 328, 329, 330, 331, 332, 333, 334, 335, 336, 337, 338, 339, 340, 341, 342, 343, 344, 345, 346, 347, 348, 349, 350, 351, 352, 353, 354, 355, 356, 357, 358, 359, 360, 361, 362, 363, 364, 365, 366, 367, 368, 369, 370, 371, 372, 373, 374, 375, 376, 377, 378, 379, 380 };
#declare LR = 3218.901119974047;  // line rate, Hz
#declare TAU = 1.1289634883842937e-05;  // exposure, s
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
// film: 328 x 4 samples spanning y/z in [0.2236725184, 0.2420084223] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 1072.420668, 4605.817309>
  right <0, 84.45182347, 0>
  up <1, 0, 0>
  aperture 28.425759 blur_samples 19 focal_point <0, 2341.858293, 10057.78> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 14491.705
  pigment { function { max(0.002, min(0.98, 0.212134 * (1 + 0.395581 * ((y / 14491.705) - 0.2328404703) / 0.00916795194 + 0.122881 * sin(17.417989 * ((y / 14491.705) - 0.2328404703) / 0.00916795194 + 5.29231)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 1567.288331, 6510.854825> + 195326 * <-0.4019349555, -0.3034582994, -0.8639220752> color rgb FL }
light_source { <0, 1567.288331, 6510.854825> + 195326 * <-0.0901919552, -0.7210658916, -0.686971172> color rgb FL * 0.5512 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, 1567.288331, 6510.854825>;  // mm
#declare V_0 = <756.8856578, 123.6491285, 2.560504914>;  // mm/s
#declare TC_0 = 0.07238495104872268;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.7874538519, 0.7874538519, 0.7703352899>] [0.44 rgb <0.7874538519, 0.7874538519, 0.7703352899>] [0.46 rgb <0.5991496699, 0.7275388849, 0.128389215>] [1.00 rgb <0.5991496699, 0.7275388849, 0.128389215>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.5386 diffuse 0.4614 phong 0.6628 phong_size 40 } }
  no_shadow
  rotate <242.280286, 35.94696677, 44.04815648>
  transform { Axis_Rotate_Trans(<-0.4045175256, 0.8450740017, -0.3495933398>, 27.131491 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
