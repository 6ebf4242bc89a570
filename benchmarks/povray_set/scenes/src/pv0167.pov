// validation scene pv0167 (seed 167)
#version 3.7;
#declare NS = 1;
#declare NLT = 105;
#declare LINES = array[105] { 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134 };
#declare LR = 156.89910696839058;  // line rate, Hz
#declare TAU = 0.003073158510456332;  // exposure, s
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
// film: 1808 x 4 samples spanning y/z in [-0.01389864345, 0.009751698363] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -9.906934928, 4777.94363>
  right <0, 113, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 20880.496
  pigment { function { max(0.002, min(0.98, 0.579836 * (1 + 0.177554 * ((y / 20880.496) - -0.002073472543) / 0.01182517091 + 0.138179 * sin(9.9585974 * ((y / 20880.496) - -0.002073472543) / 0.01182517091 + 2.0617)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -24.45030458, 7952.748148> + 238582 * <0.4851919949, 0.8518827594, 0.197191512> color rgb FL }
light_source { <0, -24.45030458, 7952.748148> + 238582 * <0.161117872, 0.97181611, -0.1720885807> color rgb FL * 0.2354 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, -24.45030458, 7952.748148>;  // mm
#declare V_0 = <-106.3483059, -56.51428642, 8.129170469>;  // mm/s
#declare TC_0 = 0.5226288510139193;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.178043269, 0.178043269, 0.1741727631>] [0.44 rgb <0.178043269, 0.178043269, 0.1741727631>] [0.46 rgb <0.1354677046, 0.1644964985, 0.02902879385>] [1.00 rgb <0.1354677046, 0.1644964985, 0.02902879385>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.5917 diffuse 0.4083 } }
  no_shadow
  rotate <270.6564545, 57.97148753, 317.5296001>
  transform { Axis_Rotate_Trans(<-0.1704561654, -0.9782155692, -0.118486269>, 0 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
