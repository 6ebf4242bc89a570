// validation scene pv0072 (seed 72)
#version 3.7;
#declare NS = 5;
#declare NLT = 35;
#declare LINES = array[35] { 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43 };
#declare LR = 437.48726635030823;  // line rate, Hz
#declare TAU = 0.001089008029320482;  // exposure, s
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
// film: 1360 x 4 samples spanning y/z in [-0.007479094408, 0.005580252597] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -6.179584534, 6508.79341>
  right <0, 85.00059172, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 23831.149
  pigment { function { max(0.002, min(0.98, 0.0242946 * (1 + -0.152789 * ((y / 23831.149) - -0.0009494209056) / 0.006529673502 + 0.0342359 * sin(22.114131 * ((y / 23831.149) - -0.0009494209056) / 0.006529673502 + 3.04552)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -0.6249272937, 7073.698791> + 212211 * <0.3578238569, -0.7559012432, -0.54824757> color rgb FL }
light_source { <0, -0.6249272937, 7073.698791> + 212211 * <0.9010142854, -0.4045239873, -0.1566320571> color rgb FL * 0.3755 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, -0.6249272937, 7073.698791>;  // mm
#declare V_0 = <-1050.881084, -65.98795259, -86.21149423>;  // mm/s
#declare TC_0 = 0.05943030117631144;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.7139050003, 0.6980404448, 0.6504467781>] [0.5 rgb <0.7139050003, 0.6980404448, 0.6504467781>] [0.5 rgb <0.5949208336, 0.06345822225, 0.04759366669>] [1.0 rgb <0.5949208336, 0.06345822225, 0.04759366669>] } }
  finish { ambient 0.4246 diffuse 0.5754 phong 0.1 phong_size 40 } }
  no_shadow
  rotate <116.5025089, 260.0352064, 176.6403391>
  transform { Axis_Rotate_Trans(<0.6099449721, -0.5404844352, -0.579520238>, 0 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
