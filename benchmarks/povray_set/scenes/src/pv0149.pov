// validation scene pv0149 (seed 149)
#version 3.7;
#declare NS = 3;
#declare NLT = 47;
#declare LINES = array[47] { 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57 };
#declare LR = 14795.822419046064;  // line rate, Hz
#declare TAU = 3.601662098779828e-05;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.204306 * sin(753.9822369 * T + 3.49574));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 2288 x 4 samples spanning y/z in [-0.09713341411, 0.0800467916] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -6.898561963, 807.481052>
  right <0, 143.0696589, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 3281.4241
  pigment { function { max(0.002, min(0.98, 0.0118292 * (1 + -0.186873 * ((y / 3281.4241) - -0.008543311258) / 0.08859010285 + 0.0282681 * sin(17.992414 * ((y / 3281.4241) - -0.008543311258) / 0.08859010285 + 3.56396)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -42.47862486, 1019.907594> + 30597.2 * <-0.2362688742, 0.788375736, -0.5680147164> color rgb FL }
light_source { <0, -42.47862486, 1019.907594> + 30597.2 * <-0.8745560708, 0.287957129, 0.3901696693> color rgb FL * 0.6625 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, -42.47862486, 1019.907594>;  // mm
#declare V_0 = <-24252.30611, 4013.136012, 1683.246519>;  // mm/s
#declare TC_0 = 0.002297945936160546;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.6852355621, 0.6852355621, 0.6703391369>] [0.44 rgb <0.6852355621, 0.6852355621, 0.6703391369>] [0.46 rgb <0.5213748842, 0.6330980737, 0.1117231895>] [1.00 rgb <0.5213748842, 0.6330980737, 0.1117231895>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.3295 diffuse 0.6705 } }
  no_shadow
  rotate <243.7481765, 221.0802478, 200.5388186>
  transform { Axis_Rotate_Trans(<-0.6562989523, -0.5022397569, 0.5630514292>, 15787.216 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
