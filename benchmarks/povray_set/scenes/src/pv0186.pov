// validation scene pv0186 (seed 186)
#version 3.7;
#declare NS = 1;
#declare NLT = 51;
#declare LINES = array[51] { 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63 };
#declare LR = 1419.022115689512;  // line rate, Hz
#declare TAU = 0.00012154075372547722;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.226491 * sin(753.9822369 * T + 3.71365));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 2624 x 4 samples spanning y/z in [-0.2635851329, -0.1272699448] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -235.117721, 1203.09411>
  right <0, 164, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 8779.6898
  pigment { function { max(0.002, min(0.98, 0.198978 * (1 + 0.132425 * ((y / 8779.6898) - -0.1954275389) / 0.06815759407 + 0.0211358 * sin(13.02073 * ((y / 8779.6898) - -0.1954275389) / 0.06815759407 + 4.92737)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -369.7778249, 1879.549217> + 56386.5 * <-0.104251339, 0.5340399631, -0.8390071371> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, -369.7778249, 1879.549217>;  // mm
#declare V_0 = <2259.954126, 267.0713507, 357.9799042>;  // mm/s
#declare TC_0 = 0.026779004766628006;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.6362202948, 0.622082066, 0.5796673797>] [0.5 rgb <0.6362202948, 0.622082066, 0.5796673797>] [0.5 rgb <0.530183579, 0.05655291509, 0.04241468632>] [1.0 rgb <0.530183579, 0.05655291509, 0.04241468632>] } }
  finish { ambient 0.1522 diffuse 0.8478 phong 0.1 phong_size 40 } }
  no_shadow
  rotate <270.6463036, 39.09444975, 42.47927098>
  transform { Axis_Rotate_Trans(<0.494503477, 0.7075165231, -0.5048630317>, 1791.8733 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
