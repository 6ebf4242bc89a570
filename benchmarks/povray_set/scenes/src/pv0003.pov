// validation scene pv0003 (seed 3)
#version 3.7;
#declare NS = 1;
#declare NLT = 103;
#declare LINES = array[103] { 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131 };
#declare LR = 22013.96336863571;  // line rate, Hz
#declare TAU = 2.2304723312319305e-06;  // exposure, s
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
// film: 2688 x 4 samples spanning y/z in [-0.3364688645, -0.1737107149] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -263.3053078, 1032.206377>
  right <0, 168, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 5997.6158
  pigment { function { max(0.002, min(0.98, 0.0929059 * (1 + 0.371814 * ((y / 5997.6158) - -0.2550897897) / 0.0813790748 + 0 * sin(13.335368 * ((y / 5997.6158) - -0.2550897897) / 0.0813790748 + 3.58116)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -419.4972521, 2175.355412> + 65260.7 * <0.1980570403, -0.4914156605, -0.8481061593> color rgb FL }
light_source { <0, -419.4972521, 2175.355412> + 65260.7 * <0.1948730477, 0.1382800706, -0.9710319857> color rgb FL * 0.3776 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, -419.4972521, 2175.355412>;  // mm
#declare V_0 = <15333.25231, 1685.339982, -1304.445413>;  // mm/s
#declare TC_0 = 0.003634057105499668;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.7472602844, 0.7472602844, 0.7310154956>] [0.44 rgb <0.7472602844, 0.7472602844, 0.7310154956>] [0.46 rgb <0.5685676077, 0.6904035236, 0.1218359159>] [1.00 rgb <0.5685676077, 0.6904035236, 0.1218359159>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.471 diffuse 0.529 phong 0.2324 phong_size 40 } }
  no_shadow
  rotate <25.5355648, 73.58636799, 261.3210883>
  transform { Axis_Rotate_Trans(<-0.1128578262, -0.9862883794, 0.120409068>, 10431.284 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
