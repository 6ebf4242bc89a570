// validation scene pv0046 (seed 46)
#version 3.7;
#declare NS = 1;
#declare NLT = 34;
#declare LINES = array[34] { 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45 };
#declare LR = 2185.562337850347;  // line rate, Hz
#declare TAU = 0.00018392578672864017;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.148509 * sin(628.3185307 * T + 6.21163));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 2112 x 4 samples spanning y/z in [-0.07414366161, 0.06425750012] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -4.714459403, 953.7492196>
  right <0, 132, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 32414.436
  pigment { function { max(0.002, min(0.98, 0.48249 * (1 + -0.37714 * ((y / 32414.436) - -0.004943080745) / 0.06920058087 + 0.124718 * sin(13.824041 * ((y / 32414.436) - -0.004943080745) / 0.06920058087 + 1.81305)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -244.2209732, 6243.81005> + 187314 * <-0.3527345437, -0.5224474968, -0.7762905093> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, -244.2209732, 6243.81005>;  // mm
#declare V_0 = <-3647.824819, -1733.491673, 1280.54542>;  // mm/s
#declare TC_0 = 0.01647173332763801;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.1085990998, 0.1085990998, 0.1062382498>] [0.44 rgb <0.1085990998, 0.1085990998, 0.1062382498>] [0.46 rgb <0.08262974988, 0.1003361249, 0.01770637497>] [1.00 rgb <0.08262974988, 0.1003361249, 0.01770637497>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.2183 diffuse 0.7817 } }
  no_shadow
  rotate <237.1255013, 174.8881985, 285.1384114>
  transform { Axis_Rotate_Trans(<0.7609607844, -0.5081663412, -0.4033678894>, 2457.4114 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
