// validation scene pv1105_a090 (seed 1105)
#version 3.7;
#declare NS = 1;
#declare NLT = 207;
#declare LINES = array[207] { 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214, 215, 216, 217, 218, 219, 220, 221, 222, 223, 224, 225, 226, 227, 228, 229, 230, 231, 232, 233, 234, 235, 236, 237, 238, 239, 240, 241, 242, 243, 244, 245, 246, 247, 248, 249, 250, 251, 252, 253, 254, 255, 256, 257, 258, 259, 260, 261, 262, 263, 264, 265, 266 };
#declare LR = 1083.7359866945555;  // line rate, Hz
#declare TAU = 0.00021522079200683212;  // exposure, s
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
// film: 2368 x 4 samples spanning y/z in [-0.03662126191, 0.02478342056] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -14.26583, 2410.208008>
  right <0, 147.9980574, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 22051.655
  pigment { function { max(0.002, min(0.98, 0.552221 * (1 + -0.323823 * ((y / 22051.655) - -0.005918920672) / 0.03070234124 + 0.131084 * sin(18.275522 * ((y / 22051.655) - -0.005918920672) / 0.03070234124 + 0.682762)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -52.76941193, 5843.11928> + 175294 * <0.4762584243, 0.7760091183, -0.4135066644> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, -52.76941193, 5843.11928>;  // mm
#declare V_0 = <404.5584725, -23.55423425, 62.39298899>;  // mm/s
#declare TC_0 = 0.15040563569099286;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.1684758618, 0.1647319538, 0.1535002296>] [0.5 rgb <0.1684758618, 0.1647319538, 0.1535002296>] [0.5 rgb <0.1403965515, 0.01497563216, 0.01123172412>] [1.0 rgb <0.1403965515, 0.01497563216, 0.01123172412>] } }
  finish { ambient 0.3193 diffuse 0.6807 phong 0.2414 phong_size 40 } }
  no_shadow
  rotate <357.9744955, 130.5136187, 53.6971511>
  transform { Axis_Rotate_Trans(<0.9363939769, -0.1121485156, -0.3325492902>, 257.44945 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
