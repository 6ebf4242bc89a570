// validation scene pv0134 (seed 134)
#version 3.7;
#declare NS = 1;
#declare NLT = 217;
#declare LINES = array[217] { 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214, 215, 216, 217, 218, 219, 220, 221, 222, 223, 224, 225, 226, 227, 228, 229, 230, 231, 232, 233, 234, 235, 236, 237, 238, 239, 240, 241, 242, 243, 244, 245, 246, 247, 248, 249, 250, 251, 252, 253, 254, 255, 256, 257, 258, 259, 260, 261, 262, 263, 264, 265, 266, 267, 268, 269, 270, 271, 272, 273, 274, 275, 276, 277, 278, 279 };
#declare LR = 13652.77119657762;  // line rate, Hz
#declare TAU = 1.7750408633064612e-05;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.216824 * sin(753.9822369 * T + 6.04426));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 2048 x 4 samples spanning y/z in [-0.04312891422, 0.05780661209] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 9.306660383, 1268.136252>
  right <0, 128, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 15292.53
  pigment { function { max(0.002, min(0.98, 0.222366 * (1 + 0.00575294 * ((y / 15292.53) - 0.007338848937) / 0.05046776316 + 0.140411 * sin(22.934407 * ((y / 15292.53) - 0.007338848937) / 0.05046776316 + 0.706892)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -59.29189697, 4639.394681> + 139182 * <0.4551239381, -0.8904275337, -0.001004071525> color rgb FL }
light_source { <0, -59.29189697, 4639.394681> + 139182 * <0.4121049825, 0.8622942758, -0.2943094721> color rgb FL * 0.3773 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, -59.29189697, 4639.394681>;  // mm
#declare V_0 = <14345.54024, 2149.033501, 4419.35136>;  // mm/s
#declare TC_0 = 0.012524929740481191;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.7729422594, 0.7729422594, 0.7729422594>] [0.925 rgb <0.7729422594, 0.7729422594, 0.7729422594>] [0.935 rgb <0.04200773149, 0.04200773149, 0.04200773149>] [1.0 rgb <0.04200773149, 0.04200773149, 0.04200773149>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.2754 diffuse 0.7246 } }
  no_shadow
  rotate <202.8104648, 138.9073032, 324.1911823>
  transform { Axis_Rotate_Trans(<0.7686324893, -0.6389910348, 0.02990909412>, 3512.9921 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
