// validation scene pv0162 (seed 162)
#version 3.7;
#declare NS = 1;
#declare NLT = 53;
#declare LINES = array[53] { 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65 };
#declare LR = 4046.066043309524;  // line rate, Hz
#declare TAU = 4.300754147752688e-05;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.0892557 * sin(753.9822369 * T + 3.09896));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 1616 x 4 samples spanning y/z in [-0.008131751534, 0.007143221869] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -3.26813977, 6612.122806>
  right <0, 101, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 34156.046
  pigment { function { max(0.002, min(0.98, 0.635913 * (1 + -0.381399 * ((y / 34156.046) - -0.0004942648323) / 0.007637486702 + 0 * sin(7.1791689 * ((y / 34156.046) - -0.0004942648323) / 0.007637486702 + 4.3789)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -67.2868684, 14822.2176> + 444667 * <0.3204687317, 0.7340341996, -0.5987433388> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, -67.2868684, 14822.2176>;  // mm
#declare V_0 = <-5770.37683, 2410.451651, -1815.561898>;  // mm/s
#declare TC_0 = 0.009638992439208807;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.1649504239, 0.1649504239, 0.1613645452>] [0.44 rgb <0.1649504239, 0.1649504239, 0.1613645452>] [0.46 rgb <0.1255057573, 0.1523998482, 0.02689409086>] [1.00 rgb <0.1255057573, 0.1523998482, 0.02689409086>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.4993 diffuse 0.5007 phong 0.7835 phong_size 40 } }
  no_shadow
  rotate <39.57489469, 9.251646026, 2.609612794>
  transform { Axis_Rotate_Trans(<0.3563698095, 0.9342072772, 0.01604126216>, 4080.9059 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
