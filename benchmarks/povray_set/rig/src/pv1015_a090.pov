// validation scene pv1015_a090 (seed 1015)
#version 3.7;
#declare NS = 2;
#declare NLT = 41;
#declare LINES = array[41] { 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51 };
#declare LR = 24.260957587722817;  // line rate, Hz
#declare TAU = 0.01925257409285263;  // exposure, s
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
// film: 2048 x 4 samples spanning y/z in [0.2723142173, 0.4083673778] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 320.1955907, 940.8087218>
  right <0, 128, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 29865.132
  pigment { function { max(0.002, min(0.98, 0.788167 * (1 + 0.244554 * ((y / 29865.132) - 0.3403407976) / 0.06802658024 + 0.238607 * sin(5.1917925 * ((y / 29865.132) - 0.3403407976) / 0.06802658024 + 1.91208)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 3283.761907, 9046.990808> + 271410 * <0.67414578, 0.735343762, -0.06926051572> color rgb FL }
light_source { <0, 3283.761907, 9046.990808> + 271410 * <0.5899235387, 0.6410661203, 0.4909424078> color rgb FL * 0.2401 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, 3283.761907, 9046.990808>;  // mm
#declare V_0 = <149.0188728, -20.01773937, 3.539854198>;  // mm/s
#declare TC_0 = 1.2777731418024263;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.09126508641, 0.09126508641, 0.09126508641>] [0.925 rgb <0.09126508641, 0.09126508641, 0.09126508641>] [0.935 rgb <0.004960059044, 0.004960059044, 0.004960059044>] [1.0 rgb <0.004960059044, 0.004960059044, 0.004960059044>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.1227 diffuse 0.8773 phong 0.4261 phong_size 40 } }
  no_shadow
  rotate <359.0119698, 96.06844179, 359.7839059>
  transform { Axis_Rotate_Trans(<-0.004974154397, -0.5739585667, 0.8188692335>, 57.185632 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
