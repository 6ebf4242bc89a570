// validation scene pv3046 (seed 3046)
#version 3.7;
#declare NS = 1;
#declare NLT = 153;
#declare LINES = array[153] { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152 };
#declare LR = 90155.3785705628;  // line rate, Hz
#declare TAU = 6.087430730697074e-06;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.198847 * sin(628.3185307 * T + 1.37693));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 3136 x 4 samples spanning y/z in [-0.02522272497, 0.03066340128] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 9.541461672, 3507.454268>
  right <0, 196.0180321, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 21058.474
  pigment { function { max(0.002, min(0.98, 0.844569 * (1 + 0.129859 * ((y / 21058.474) - 0.002720338155) / 0.02794306313 + 0.245169 * sin(9.6433316 * ((y / 21058.474) - 0.002720338155) / 0.02794306313 + 2.56345)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -60.97874248, 6649.770705> + 199493 * <0.3097115296, 0.1412357705, -0.9402825243> color rgb FL }
light_source { <0, -60.97874248, 6649.770705> + 199493 * <-0.7549939962, -0.1231865168, 0.6440567893> color rgb FL * 0.5711 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, -60.97874248, 6649.770705>;  // mm
#declare V_0 = <-31509.0962, 6880.074251, -490.1142468>;  // mm/s
#declare TC_0 = 0.0005767820048506662;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.2199025918, 0.2199025918, 0.2151221007>] [0.44 rgb <0.2199025918, 0.2199025918, 0.2151221007>] [0.46 rgb <0.1673171894, 0.2031708729, 0.03585368345>] [1.00 rgb <0.1673171894, 0.2031708729, 0.03585368345>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.494 diffuse 0.506 phong 0.2016 phong_size 40 } }
  no_shadow
  rotate <355.2064743, 352.4750465, 313.6463627>
  transform { Axis_Rotate_Trans(<-0.7446573645, 0.3863838383, 0.5442361059>, 13117.837 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
