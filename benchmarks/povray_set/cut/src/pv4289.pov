// validation scene pv4289 (seed 4289)
#version 3.7;
#declare NS = 2;
#declare NLT = 209;
#declare LINES = array[209] { 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214, 215, 216, 217, 218, 219, 220, 221, 222, 223, 224, 225, 226, 227, 228, 229, 230, 231, 232, 233, 234, 235, 236, 237, 238, 239, 240, 241, 242, 243, 244, 245, 246, 247, 248, 249, 250, 251, 252, 253, 254, 255, 256, 257, 258, 259, 260, 261, 262, 263, 264, 265, 266, 267, 268, 269 };
#declare LR = 33754.46913685093;  // line rate, Hz
#declare TAU = 1.9883428660539992e-05;  // exposure, s
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
// film: 2432 x 4 samples spanning y/z in [-0.1148948056, -0.04867076324] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -187.7110304, 2295.238928>
  right <0, 152, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 18640.186
  pigment { function { max(0.002, min(0.98, 0.0210646 * (1 + 0.158768 * ((y / 18640.186) - -0.08178278443) / 0.03311202119 + 0 * sin(19.303024 * ((y / 18640.186) - -0.08178278443) / 0.03311202119 + 2.8989)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -199.1721621, 3254.849338> + 97645.5 * <-0.5975935354, 0.352302556, -0.7202533412> color rgb FL }
light_source { <0, -199.1721621, 3254.849338> + 97645.5 * <0.7440280557, 0.6564940229, -0.1242491456> color rgb FL * 0.5667 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, -199.1721621, 3254.849338>;  // mm
#declare V_0 = <11256.87182, -18287.01242, -362.4435668>;  // mm/s
#declare TC_0 = 0.004888241593462472;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.7771487971, 0.7771487971, 0.7602542581>] [0.44 rgb <0.7771487971, 0.7771487971, 0.7602542581>] [0.46 rgb <0.5913088674, 0.7180179104, 0.126709043>] [1.00 rgb <0.5913088674, 0.7180179104, 0.126709043>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.1901 diffuse 0.8099 } }
  no_shadow
  rotate <304.9783803, 76.95555001, 107.2181574>
  transform { Axis_Rotate_Trans(<-0.7261870682, -0.3893626004, -0.5666119548>, 7805.6248 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
