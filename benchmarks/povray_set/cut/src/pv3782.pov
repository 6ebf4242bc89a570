// validation scene pv3782 (seed 3782)
#version 3.7;
#declare NS = 1;
#declare NLT = 95;
#declare LINES = array[95] { 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133 };
#declare LR = 21451.429270757;  // line rate, Hz
#declare TAU = 2.6088910249121276e-06;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.24433 * sin(628.3185307 * T + 4.76051));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 1456 x 4 samples spanning y/z in [-0.01719442526, 0.02130666228] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 4.859779195, 2363.569598>
  right <0, 91, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 30905.158
  pigment { function { max(0.002, min(0.98, 0.0200724 * (1 + -0.191878 * ((y / 30905.158) - 0.002056118508) / 0.01925054377 + 0 * sin(14.68582 * ((y / 30905.158) - 0.002056118508) / 0.01925054377 + 0.75451)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -21.01582005, 5551.571582> + 166547 * <0.2851916217, 0.4124267451, -0.8651993521> color rgb FL }
light_source { <0, -21.01582005, 5551.571582> + 166547 * <0.2897751568, -0.2536074432, 0.9228833205> color rgb FL * 0.3488 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, -21.01582005, 5551.571582>;  // mm
#declare V_0 = <11323.98053, 1296.397124, 1419.042454>;  // mm/s
#declare TC_0 = 0.004941395683340375;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.659019317, 0.659019317, 0.6446928101>] [0.44 rgb <0.659019317, 0.659019317, 0.6446928101>] [0.46 rgb <0.5014277412, 0.6088765429, 0.1074488017>] [1.00 rgb <0.5014277412, 0.6088765429, 0.1074488017>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.5907 diffuse 0.4093 phong 0.718 phong_size 40 } }
  no_shadow
  rotate <266.9081679, 59.95839294, 281.6817723>
  transform { Axis_Rotate_Trans(<-0.5223807571, -0.4150363882, 0.7448913619>, 0 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
