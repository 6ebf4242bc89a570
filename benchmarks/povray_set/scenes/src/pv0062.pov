// validation scene pv0062 (seed 62)
#version 3.7;
#declare NS = 2;
#declare NLT = 47;
#declare LINES = array[47] { 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58 };
#declare LR = 20.0;  // line rate, Hz
#declare TAU = 0.00686220282428811;  // exposure, s
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
// film: 2400 x 4 samples spanning y/z in [-0.04792083699, 0.0952861461] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 24.80604022, 1047.434956>
  right <0, 150, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 3649.7319
  pigment { function { max(0.002, min(0.98, 0.146104 * (1 + 0.313164 * ((y / 3649.7319) - 0.02368265455) / 0.07160349155 + 0.134728 * sin(13.17683 * ((y / 3649.7319) - 0.02368265455) / 0.07160349155 + 5.04818)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 66.24602612, 1319.006294> + 39570.2 * <-0.6095055407, -0.567277908, -0.5538039102> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, 66.24602612, 1319.006294>;  // mm
#declare V_0 = <35.00056542, -39.66244019, -1.55752384>;  // mm/s
#declare TC_0 = 1.75;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.7762005425, 0.7589516416, 0.7072049388>] [0.5 rgb <0.7762005425, 0.7589516416, 0.7072049388>] [0.5 rgb <0.6468337855, 0.06899560378, 0.05174670284>] [1.0 rgb <0.6468337855, 0.06899560378, 0.05174670284>] } }
  finish { ambient 0.1642 diffuse 0.8358 phong 0.673 phong_size 40 } }
  no_shadow
  rotate <191.8473738, 291.4766607, 218.241743>
  transform { Axis_Rotate_Trans(<-0.4950314415, 0.8076803242, -0.3203066746>, 0 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
