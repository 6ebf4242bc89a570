// validation scene pv0244 (seed 244)
#version 3.7;
#declare NS = 1;
#declare NLT = 29;
#declare LINES = array[29] { 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34 };
#declare LR = 355.58358242472923;  // line rate, Hz
#declare TAU = 0.0002326763231569369;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.292878 * sin(628.3185307 * T + 5.22136));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 1328 x 4 samples spanning y/z in [-0.04908794467, 0.03609663441] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -6.329072487, 974.3547587>
  right <0, 83, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 3504.1764
  pigment { function { max(0.002, min(0.98, 0.0231209 * (1 + 0.3172 * ((y / 3504.1764) - -0.00649565513) / 0.04259228954 + 0 * sin(17.101966 * ((y / 3504.1764) - -0.00649565513) / 0.04259228954 + 0.522148)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -8.527516733, 1160.599713> + 34818 * <-0.6393294194, 0.5257054387, -0.5611521052> color rgb FL }
light_source { <0, -8.527516733, 1160.599713> + 34818 * <-0.6194453602, -0.1968370256, 0.7599622563> color rgb FL * 0.4309 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, -8.527516733, 1160.599713>;  // mm
#declare V_0 = <1085.000367, -67.81441066, -222.3599834>;  // mm/s
#declare TC_0 = 0.056245566411192924;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.8484625158, 0.8296077933, 0.7730436255>] [0.5 rgb <0.8484625158, 0.8296077933, 0.7730436255>] [0.5 rgb <0.7070520965, 0.0754188903, 0.05656416772>] [1.0 rgb <0.7070520965, 0.0754188903, 0.05656416772>] } }
  finish { ambient 0.13 diffuse 0.87 phong 0.1 phong_size 40 } }
  no_shadow
  rotate <314.4344818, 291.4567817, 164.9903578>
  transform { Axis_Rotate_Trans(<0.6758477654, -0.4447963184, 0.5876955276>, 0 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
