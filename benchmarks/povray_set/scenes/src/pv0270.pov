// validation scene pv0270 (seed 270)
#version 3.7;
#declare NS = 1;
#declare NLT = 41;
#declare LINES = array[41] { 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51 };
#declare LR = 221.82354586019477;  // line rate, Hz
#declare TAU = 0.0006739118006188629;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.0838715 * sin(753.9822369 * T + 4.26601));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 1664 x 4 samples spanning y/z in [-0.02453191877, 0.03216514316] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 7.001182286, 1834.397085>
  right <0, 104.0049251, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 13274.545
  pigment { function { max(0.002, min(0.98, 0.0432823 * (1 + 0.00741613 * ((y / 13274.545) - 0.003816612196) / 0.02834853097 + 0 * sin(10.872563 * ((y / 13274.545) - 0.003816612196) / 0.02834853097 + 0.582047)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -3.275988166, 3576.363629> + 107291 * <0.6468403021, 0.09295155039, -0.7569396495> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, -3.275988166, 3576.363629>;  // mm
#declare V_0 = <-406.4516658, 170.9461619, -132.9185835>;  // mm/s
#declare TC_0 = 0.13975071888688445;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.669725075, 0.669725075, 0.6551658342>] [0.44 rgb <0.669725075, 0.669725075, 0.6551658342>] [0.46 rgb <0.5095734266, 0.6187677323, 0.1091943057>] [1.00 rgb <0.5095734266, 0.6187677323, 0.1091943057>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.4546 diffuse 0.5454 } }
  no_shadow
  rotate <176.2071904, 97.87653626, 316.2842135>
  transform { Axis_Rotate_Trans(<0.2402409833, 0.3457989276, 0.9070321778>, 44.572176 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
