// validation scene pv1059_a000 (seed 1059)
#version 3.7;
#declare NS = 1;
#declare NLT = 69;
#declare LINES = array[69] { 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87 };
#declare LR = 100.63532429354994;  // line rate, Hz
#declare TAU = 0.0025602844053376475;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.308665 * sin(628.3185307 * T + 5.6462));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 2864 x 4 samples spanning y/z in [-0.1964213053, -0.1425468029] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -562.3374018, 3317.936928>
  right <0, 178.7522007, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 24664.959
  pigment { function { max(0.002, min(0.98, 0.0173456 * (1 + -0.210949 * ((y / 24664.959) - -0.1694840541) / 0.02693725115 + 0.211291 * sin(6.2676743 * ((y / 24664.959) - -0.1694840541) / 0.02693725115 + 0.910852)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -911.952659, 5389.085534> + 161673 * <0.3822810035, -0.6011376993, -0.7017796669> color rgb FL }
light_source { <0, -911.952659, 5389.085534> + 161673 * <-0.521972308, -0.8202747096, 0.2338681475> color rgb FL * 0.4843 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, -911.952659, 5389.085534>;  // mm
#declare V_0 = <115.6434268, -47.47893605, -0.1550649189>;  // mm/s
#declare TC_0 = 0.5266540389476039;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.8498226579, 0.8309377099, 0.7742828661>] [0.5 rgb <0.8498226579, 0.8309377099, 0.7742828661>] [0.5 rgb <0.7081855482, 0.07553979181, 0.05665484386>] [1.0 rgb <0.7081855482, 0.07553979181, 0.05665484386>] } }
  finish { ambient 0.4599 diffuse 0.5401 phong 0.1 phong_size 40 } }
  no_shadow
  rotate <259.3251524, 9.951389166, 79.76522267>
  transform { Axis_Rotate_Trans(<0.7625402818, -0.6181877455, -0.1907255359>, 100.30475 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
