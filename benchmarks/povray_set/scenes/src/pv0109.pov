// validation scene pv0109 (seed 109)
#version 3.7;
#declare NS = 1;
#declare NLT = 77;
#declare LINES = array[77] { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76 };
#declare LR = 19832.384322080838;  // line rate, Hz
#declare TAU = 9.925166373951471e-06;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.26807 * sin(628.3185307 * T + 2.10483));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 3056 x 4 samples spanning y/z in [-0.2492935092, -0.01870673934] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -109.1003312, 814.1808208>
  right <0, 187.7393255, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 14224.173
  pigment { function { max(0.002, min(0.98, 0.0142046 * (1 + -0.392866 * ((y / 14224.173) - -0.1340001243) / 0.1152933849 + 0.00508383 * sin(11.130475 * ((y / 14224.173) - -0.1340001243) / 0.1152933849 + 6.04499)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -91.89827811, 2391.586744> + 71747.6 * <0.6192820952, -0.3283895375, -0.7131970262> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, -91.89827811, 2391.586744>;  // mm
#declare V_0 = <8720.099974, -477.9494928, 297.5496717>;  // mm/s
#declare TC_0 = -0.0002521129037638271;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.7838616168, 0.7838616168, 0.7668211469>] [0.44 rgb <0.7838616168, 0.7838616168, 0.7668211469>] [0.46 rgb <0.5964164476, 0.724219972, 0.1278035245>] [1.00 rgb <0.5964164476, 0.724219972, 0.1278035245>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.5646 diffuse 0.4354 } }
  no_shadow
  rotate <12.26398831, 280.823383, 220.7987683>
  transform { Axis_Rotate_Trans(<-0.2181234621, 0.751751566, -0.6223276776>, 6242.2387 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
