// validation scene pv0168 (seed 168)
#version 3.7;
#declare NS = 1;
#declare NLT = 227;
#declare LINES = array[227] { 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214, 215, 216, 217, 218, 219, 220, 221, 222, 223, 224, 225, 226, 227, 228, 229, 230, 231, 232, 233, 234, 235, 236, 237, 238, 239, 240, 241, 242, 243, 244, 245, 246, 247, 248, 249, 250, 251, 252, 253, 254, 255, 256, 257, 258, 259, 260, 261, 262, 263, 264, 265, 266, 267, 268, 269, 270, 271, 272, 273, 274, 275, 276, 277, 278, 279, 280, 281, 282, 283, 284, 285, 286, 287, 288, 289, 290, 291, 292 };
#declare LR = 1671.2508785499278;  // line rate, Hz
#declare TAU = 0.00017799195657644762;  // exposure, s
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
// film: 1120 x 4 samples spanning y/z in [0.2768262303, 0.3394729346] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 344.3193225, 1117.377216>
  right <0, 70, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 18153.863
  pigment { function { max(0.002, min(0.98, 0.0742927 * (1 + -0.163626 * ((y / 18153.863) - 0.3081495825) / 0.03132335214 + 0.0447279 * sin(20.89314 * ((y / 18153.863) - 0.3081495825) / 0.03132335214 + 2.94156)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 1230.037356, 3858.133155> + 115744 * <0.0266045713, 0.2041585675, -0.9785762495> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, 1230.037356, 3858.133155>;  // mm
#declare V_0 = <-527.1968919, -91.05754606, 205.2112081>;  // mm/s
#declare TC_0 = 0.10710540368140932;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.8890535984, 0.8890535984, 0.8697263463>] [0.44 rgb <0.8890535984, 0.8890535984, 0.8697263463>] [0.46 rgb <0.6764538249, 0.8214082159, 0.144954391>] [1.00 rgb <0.6764538249, 0.8214082159, 0.144954391>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.2493 diffuse 0.7507 phong 0.6164 phong_size 40 } }
  no_shadow
  rotate <271.5778684, 320.457587, 267.4399594>
  transform { Axis_Rotate_Trans(<-0.4255395974, -0.7795968303, 0.4595049872>, 481.75408 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
