// validation scene pv0005 (seed 5)
#version 3.7;
#declare NS = 1;
#declare NLT = 219;
#declare LINES = array[219] { 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214, 215, 216, 217, 218, 219, 220, 221, 222, 223, 224, 225, 226, 227, 228, 229, 230, 231, 232, 233, 234, 235, 236, 237, 238, 239, 240, 241, 242, 243, 244, 245, 246, 247, 248, 249, 250, 251, 252, 253, 254, 255, 256, 257, 258, 259, 260, 261, 262, 263, 264, 265, 266, 267, 268, 269, 270, 271, 272, 273, 274, 275, 276, 277, 278, 279, 280, 281 };
#declare LR = 16051.686687843223;  // line rate, Hz
#declare TAU = 5.49851873368241e-05;  // exposure, s
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
// film: 1840 x 4 samples spanning y/z in [-0.03079753791, 0.02109959643] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -10.74631811, 2216.206013>
  right <0, 115.0147412, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 15494.859
  pigment { function { max(0.002, min(0.98, 0.102668 * (1 + 0.284929 * ((y / 15494.859) - -0.00484897074) / 0.02594856717 + 0.102082 * sin(8.9334401 * ((y / 15494.859) - -0.00484897074) / 0.02594856717 + 5.57383)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -38.64778366, 5755.58038> + 172667 * <0.5763111167, 0.05167504306, -0.8155949894> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, -38.64778366, 5755.58038>;  // mm
#declare V_0 = <-5234.58572, -446.6203504, 897.4023768>;  // mm/s
#declare TC_0 = 0.010715384828079441;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.663552002, 0.663552002, 0.6491269585>] [0.44 rgb <0.663552002, 0.663552002, 0.6491269585>] [0.46 rgb <0.5048765232, 0.6130643497, 0.1081878264>] [1.00 rgb <0.5048765232, 0.6130643497, 0.1081878264>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.5441 diffuse 0.4559 } }
  no_shadow
  rotate <167.5508415, 309.1160409, 76.78296099>
  transform { Axis_Rotate_Trans(<0.7633837933, 0.1755504598, 0.6216327052>, 3241.9899 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
