// validation scene pv0119 (seed 119)
#version 3.7;
#declare NS = 1;
#declare NLT = 61;
#declare LINES = array[61] { 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76 };
#declare LR = 7130.3661932564355;  // line rate, Hz
#declare TAU = 5.147203430693324e-06;  // exposure, s
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
// film: 348 x 4 samples spanning y/z in [-0.2566920092, -0.1730905663] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -218.6361136, 1017.426606>
  right <0, 85.05833232, 0>
  up <1, 0, 0>
  aperture 48.630329 blur_samples 19 focal_point <0, -1898.715935, 8835.7046> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 26974.539
  pigment { function { max(0.002, min(0.98, 0.106117 * (1 + -0.252123 * ((y / 26974.539) - -0.2148912877) / 0.04180072144 + 0 * sin(22.77382 * ((y / 26974.539) - -0.2148912877) / 0.04180072144 + 0.786772)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -1552.98042, 6335.897582> + 190077 * <-0.9135184792, -0.3859518425, -0.1285502368> color rgb FL }
light_source { <0, -1552.98042, 6335.897582> + 190077 * <-0.2717190818, -0.9021743169, -0.3350376733> color rgb FL * 0.3539 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, -1552.98042, 6335.897582>;  // mm
#declare V_0 = <28335.05205, -1651.190757, -493.632224>;  // mm/s
#declare TC_0 = 0.006451281568610689;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.8323040317, 0.8323040317, 0.8323040317>] [0.925 rgb <0.8323040317, 0.8323040317, 0.8323040317>] [0.935 rgb <0.04523391477, 0.04523391477, 0.04523391477>] [1.0 rgb <0.04523391477, 0.04523391477, 0.04523391477>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.2956 diffuse 0.7044 phong 0.4464 phong_size 40 } }
  no_shadow
  rotate <92.12276148, 59.70729938, 192.0581757>
  transform { Axis_Rotate_Trans(<0.2320715804, -0.006066158156, 0.9726797948>, 0 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
