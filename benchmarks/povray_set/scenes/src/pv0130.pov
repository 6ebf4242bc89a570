// validation scene pv0130 (seed 130)
#version 3.7;
#declare NS = 3;
#declare NLT = 77;
#declare LINES = array[77] { 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96 };
#declare LR = 160.45847492959592;  // line rate, Hz
#declare TAU = 0.00525855647967495;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.214434 * sin(628.3185307 * T + 2.80604));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 2608 x 4 samples spanning y/z in [-0.06240602148, 0.05369963216] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -6.111422717, 1403.893737>
  right <0, 163, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 37377.578
  pigment { function { max(0.002, min(0.98, 0.0397448 * (1 + 0.0563366 * ((y / 37377.578) - -0.004353194658) / 0.05805282682 + 0 * sin(24.388192 * ((y / 37377.578) - -0.004353194658) / 0.05805282682 + 4.01004)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -107.3669215, 7625.902543> + 228777 * <-0.6940229219, -0.2455898701, -0.6767701232> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, -107.3669215, 7625.902543>;  // mm
#declare V_0 = <-508.1488886, 425.6910213, 3.378797653>;  // mm/s
#declare TC_0 = 0.36146423568744845;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.741662097, 0.741662097, 0.741662097>] [0.925 rgb <0.741662097, 0.741662097, 0.741662097>] [0.935 rgb <0.04030772266, 0.04030772266, 0.04030772266>] [1.0 rgb <0.04030772266, 0.04030772266, 0.04030772266>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.2818 diffuse 0.7182 phong 0.3345 phong_size 40 } }
  no_shadow
  rotate <113.156628, 275.4256308, 300.9508226>
  transform { Axis_Rotate_Trans(<-0.800844638, 0.5575280937, 0.2186556439>, 269.2409 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
