// validation scene pv0260 (seed 260)
#version 3.7;
#declare NS = 2;
#declare NLT = 120;
#declare LINES = array[120] { 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152 };
#declare LR = 3199.3138259481266;  // line rate, Hz
#declare TAU = 0.00011131287126209171;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.266097 * sin(628.3185307 * T + 1.13236));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 2224 x 4 samples spanning y/z in [-0.05932519494, 0.09070719893] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 14.53718908, 926.4665877>
  right <0, 139, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 3832.9193
  pigment { function { max(0.002, min(0.98, 0.0782964 * (1 + -0.261309 * ((y / 3832.9193) - 0.015691002) / 0.07501619694 + 0 * sin(12.728962 * ((y / 3832.9193) - 0.015691002) / 0.07501619694 + 2.15424)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -33.6106863, 1201.192979> + 36035.8 * <0.3912910138, 0.6546350747, -0.6467953784> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, -33.6106863, 1201.192979>;  // mm
#declare V_0 = <2948.733118, 268.1867375, 356.6023719>;  // mm/s
#declare TC_0 = 0.022504825696073306;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.8882752247, 0.8882752247, 0.8689648938>] [0.44 rgb <0.8882752247, 0.8882752247, 0.8689648938>] [0.46 rgb <0.675861584, 0.8206890663, 0.1448274823>] [1.00 rgb <0.675861584, 0.8206890663, 0.1448274823>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.345 diffuse 0.655 phong 0.4515 phong_size 40 } }
  no_shadow
  rotate <241.3940695, 56.14184291, 258.2105271>
  transform { Axis_Rotate_Trans(<-0.3624732391, -0.5667191066, -0.7398936445>, 1259.2195 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
// ball 1: tennis
#declare C0_1 = <0, 76.56380663, 1331.205734>;  // mm
#declare V_1 = <3394.40204, 106.0518273, -269.5478793>;  // mm/s
#declare TC_1 = 0.036941250318469385;  // s
#declare P_1 = C0_1 + V_1 * (T - TC_1);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.8882752247, 0.8882752247, 0.8689648938>] [0.44 rgb <0.8882752247, 0.8882752247, 0.8689648938>] [0.46 rgb <0.675861584, 0.8206890663, 0.1448274823>] [1.00 rgb <0.675861584, 0.8206890663, 0.1448274823>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.345 diffuse 0.655 phong 0.4515 phong_size 40 } }
  no_shadow
  rotate <244.0734487, 281.1068079, 329.1821986>
  transform { Axis_Rotate_Trans(<-0.3624732391, -0.5667191066, -0.7398936445>, 1259.2195 * (T - TC_1)) }
  scale 33.5
  translate P_1 }
#end
