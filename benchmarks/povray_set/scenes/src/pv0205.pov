// validation scene pv0205 (seed 205)
#version 3.7;
#declare NS = 1;
#declare NLT = 63;
#declare LINES = array[63] { 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79 };
#declare LR = 64.33962117332791;  // line rate, Hz
#declare TAU = 0.0006348401173295183;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.066531 * sin(628.3185307 * T + 4.60741));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 1520 x 4 samples spanning y/z in [-0.01971070981, 0.002223755194] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -37.87010916, 4331.241202>
  right <0, 95.00345856, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 21331.373
  pigment { function { max(0.002, min(0.98, 0.629125 * (1 + -0.183818 * ((y / 21331.373) - -0.008743477308) / 0.0109672325 + 0 * sin(4.8521711 * ((y / 21331.373) - -0.008743477308) / 0.0109672325 + 4.13602)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -36.69300209, 3999.238054> + 119977 * <-0.4934362796, -0.8504927016, 0.1821614737> color rgb FL }
light_source { <0, -36.69300209, 3999.238054> + 119977 * <0.883070561, -0.373546495, 0.2839883807> color rgb FL * 0.4452 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, -36.69300209, 3999.238054>;  // mm
#declare V_0 = <-81.1486416, -2.486506405, 4.432836448>;  // mm/s
#declare TC_0 = 0.746041072742568;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.1316466963, 0.1287212141, 0.1199447677>] [0.5 rgb <0.1316466963, 0.1287212141, 0.1199447677>] [0.5 rgb <0.1097055802, 0.01170192856, 0.008776446418>] [1.0 rgb <0.1097055802, 0.01170192856, 0.008776446418>] } }
  finish { ambient 0.1293 diffuse 0.8707 phong 0.3171 phong_size 40 } }
  no_shadow
  rotate <28.05359907, 353.6049828, 331.4463329>
  transform { Axis_Rotate_Trans(<0.4492077414, -0.7601969667, 0.469375092>, 31.067514 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
