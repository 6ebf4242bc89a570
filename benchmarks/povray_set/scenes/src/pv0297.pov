// validation scene pv0297 (seed 297)
#version 3.7;
#declare NS = 1;
#declare NLT = 53;
#declare LINES = array[53] { 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65 };
#declare LR = 327.1992697603071;  // line rate, Hz
#declare TAU = 0.00021281255238733812;  // exposure, s
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
// film: 1968 x 4 samples spanning y/z in [-0.03193690438, 0.03806183704] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 5.381287586, 1757.174451>
  right <0, 123, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 16278.875
  pigment { function { max(0.002, min(0.98, 0.71518 * (1 + -0.185634 * ((y / 16278.875) - 0.003062466327) / 0.03499937071 + 0.063947 * sin(16.108495 * ((y / 16278.875) - 0.003062466327) / 0.03499937071 + 5.81641)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -172.5244605, 6907.883209> + 207236 * <-0.3427466475, 0.6774576264, -0.6508270892> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, -172.5244605, 6907.883209>;  // mm
#declare V_0 = <481.8529159, -23.8586674, 39.1206491>;  // mm/s
#declare TC_0 = 0.11919342004818598;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.187897194, 0.187897194, 0.1838124724>] [0.44 rgb <0.187897194, 0.187897194, 0.1838124724>] [0.46 rgb <0.1429652563, 0.1736006684, 0.03063541206>] [1.00 rgb <0.1429652563, 0.1736006684, 0.03063541206>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.4637 diffuse 0.5363 } }
  no_shadow
  rotate <255.8578617, 203.9245118, 77.16408913>
  transform { Axis_Rotate_Trans(<0.5198433537, -0.8472686287, 0.10908143>, 391.83566 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
