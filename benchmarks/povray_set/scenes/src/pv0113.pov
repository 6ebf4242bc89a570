// validation scene pv0113 (seed 113)
#version 3.7;
#declare NS = 2;
#declare NLT = 83;
#declare LINES = array[83] { 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104 };
#declare LR = 658.8636332683972;  // line rate, Hz
#declare TAU = 0.0007454779175869459;  // exposure, s
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
// film: 1616 x 4 samples spanning y/z in [-0.02187244972, 0.01796254592] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -4.956700477, 2535.459044>
  right <0, 101, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 7934.4333
  pigment { function { max(0.002, min(0.98, 0.210857 * (1 + 0.0650303 * ((y / 7934.4333) - -0.0019549519) / 0.01991749782 + 0.19593 * sin(10.782997 * ((y / 7934.4333) - -0.0019549519) / 0.01991749782 + 2.23637)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -12.18790677, 3099.611552> + 92988.3 * <0.05993458155, -0.5902187446, -0.8050153287> color rgb FL }
light_source { <0, -12.18790677, 3099.611552> + 92988.3 * <0.7022325212, 0.6309290065, -0.3298455318> color rgb FL * 0.2095 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, -12.18790677, 3099.611552>;  // mm
#declare V_0 = <575.8508796, -44.04101084, -46.69803514>;  // mm/s
#declare TC_0 = 0.09561917947645486;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.8918737653, 0.8918737653, 0.8724852052>] [0.44 rgb <0.8918737653, 0.8918737653, 0.8724852052>] [0.46 rgb <0.678599604, 0.8240138049, 0.1454142009>] [1.00 rgb <0.678599604, 0.8240138049, 0.1454142009>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.4221 diffuse 0.5779 } }
  no_shadow
  rotate <87.92155283, 26.53820629, 164.5681501>
  transform { Axis_Rotate_Trans(<0.3820600871, -0.0772019377, 0.9209071347>, 4.4307219 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
