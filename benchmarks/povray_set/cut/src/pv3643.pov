// validation scene pv3643 (seed 3643)
#version 3.7;
#declare NS = 1;
#declare NLT = 245;
#declare LINES = array[245] { 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214, 215, 216, 217, 218, 219, 220, 221, 222, 223, 224, 225, 226, 227, 228, 229, 230, 231, 232, 233, 234, 235, 236, 237, 238, 239, 240, 241, 242, 243, 244, 245, 246, 247, 248, 249, 250, 251, 252, 253, 254, 255, 256, 257, 258, 259, 260, 261, 262, 263, 264, 265, 266, 267, 268, 269, 270, 271, 272, 273, 274, 275, 276, 277, 278, 279, 280, 281, 282, 283, 284, 285, 286, 287, 288, 289, 290, 291, 292, 293, 294, 295, 296, 297, 298, 299, 300, 301, 302, 303, 304, 305, 306, 307, 308, 309, 310, 311, 312, 313, 314, 315 };
#declare LR = 10388.803890950288;  // line rate, Hz
#declare TAU = 7.266351854884862e-06;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.228188 * sin(753.9822369 * T + 5.8083));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 2704 x 4 samples spanning y/z in [-0.2336514131, -0.2057772259] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -1347.834168, 6134.484868>
  right <0, 170.9937795, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 29066.86
  pigment { function { max(0.002, min(0.98, 0.0307055 * (1 + 0.109265 * ((y / 29066.86) - -0.2197143195) / 0.01393709359 + 0.193381 * sin(8.3958635 * ((y / 29066.86) - -0.2197143195) / 0.01393709359 + 6.24211)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -1531.216792, 7334.8876> + 220047 * <0.3657619547, -0.4669774479, -0.8050777948> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, -1531.216792, 7334.8876>;  // mm
#declare V_0 = <-3211.902297, 519.0065312, 1554.815367>;  // mm/s
#declare TC_0 = 0.01857769210256464;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.8981260745, 0.8781677173, 0.8182926457>] [0.5 rgb <0.8981260745, 0.8781677173, 0.8182926457>] [0.5 rgb <0.7484383954, 0.07983342884, 0.05987507163>] [1.0 rgb <0.7484383954, 0.07983342884, 0.05987507163>] } }
  finish { ambient 0.2324 diffuse 0.7676 phong 0.1 phong_size 40 } }
  no_shadow
  rotate <142.1013151, 345.2489889, 215.3089139>
  transform { Axis_Rotate_Trans(<-0.15739624, 0.935649237, 0.3158906915>, 2816.7251 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
