// validation scene pv0079 (seed 79)
#version 3.7;
#declare NS = 1;
#declare NLT = 298;
#declare LINES = array[298] { 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214, 215, 216, 217, 218, 219, 220, 221, 222, 223, 224, 225, 226, 227, 228, 229, 230, 231, 232, 233, 234, 235, 236, 237, 238, 239, 240, 241, 242, 243, 244, 245, 246, 247, 248, 249, 250, 251, 252, 253, 254, 255, 256, 257, 258, 259, 260, 261, 262, 263, 264, 265, 266, 267, 268, 269, 270, 271, 272, 273, 274, 278, 279, 280, 281, 282, 283, 284, 285, 286, 287, 288, 289, 290, 291, 292, 293, 294, 295, 296, 297, 298, 299, 300, 301, 302, 303, 304, 305, 306, 307, 308, 309, 310, 311, 312, 313, 314, 315, 316, 317, 318, 319, 320, 321, 322, 323, 324, 325, 326, 327, 328, 329, 330, 331, 332, 333, 334, 335, 336, 337, 338, 339, 340, 341, 342, 343, 344, 345, 346, 347, 348, 349, 350, 351, 352, 353, 354, 355, 356, 357, 358, 359, 360, 361, 362, 363, 364, 365, 366, 367, 368, 369, 370, 371, 372, 373, 374, 375, 376, 377, 378, 379, 380, 381, 382, 383, 384, 385, 386, 387, 388 };
#declare LR = 10200.398562825425;  // line rate, Hz
#declare TAU = 5.196117056326038e-06;  // exposure, s
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
// film: 2624 x 4 samples spanning y/z in [-0.04001752145, 0.0851848718] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 29.56867133, 1309.294041>
  right <0, 163.9267474, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 11792.86
  pigment { function { max(0.002, min(0.98, 0.0272212 * (1 + -0.0747905 * ((y / 11792.86) - 0.02258367517) / 0.06260119663 + 0.218819 * sin(13.520596 * ((y / 11792.86) - 0.02258367517) / 0.06260119663 + 6.25283)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -45.75543468, 3117.577633> + 93527.3 * <0.4507608, 0.3236829307, -0.8318918569> color rgb FL }
light_source { <0, -45.75543468, 3117.577633> + 93527.3 * <0.3909691973, 0.6145710277, -0.6851609583> color rgb FL * 0.6703 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, -45.75543468, 3117.577633>;  // mm
#declare V_0 = <-3863.441644, -4649.336777, 68.3247733>;  // mm/s
#declare TC_0 = 0.017744404680385795;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.7397272741, 0.7397272741, 0.7236462464>] [0.44 rgb <0.7397272741, 0.7397272741, 0.7236462464>] [0.46 rgb <0.5628359694, 0.6834436772, 0.1206077077>] [1.00 rgb <0.5628359694, 0.6834436772, 0.1206077077>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.2216 diffuse 0.7784 } }
  no_shadow
  rotate <162.5920073, 93.78822269, 36.0672607>
  transform { Axis_Rotate_Trans(<0.5526382364, 0.8334146376, -0.003319863355>, 4863.1101 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
// ball 1: tennis
#declare C0_1 = <0, 169.7648535, 3203.324296>;  // mm
#declare V_1 = <-6638.618208, -120.3306878, -16.80219735>;  // mm/s
#declare TC_1 = 0.03262112996590358;  // s
#declare P_1 = C0_1 + V_1 * (T - TC_1);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.7397272741, 0.7397272741, 0.7236462464>] [0.44 rgb <0.7397272741, 0.7397272741, 0.7236462464>] [0.46 rgb <0.5628359694, 0.6834436772, 0.1206077077>] [1.00 rgb <0.5628359694, 0.6834436772, 0.1206077077>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.2216 diffuse 0.7784 } }
  no_shadow
  rotate <329.2763458, 77.5283272, 128.817705>
  transform { Axis_Rotate_Trans(<0.5526382364, 0.8334146376, -0.003319863355>, 4863.1101 * (T - TC_1)) }
  scale 33.5
  translate P_1 }
#end
