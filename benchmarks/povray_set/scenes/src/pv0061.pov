// validation scene pv0061 (seed 61)
#version 3.7;
#declare NS = 1;
#declare NLT = 79;
#declare LINES = array[79] { 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100 };
#declare LR = 41.766678843418894;  // line rate, Hz
#declare TAU = 0.003076289344778014;  // exposure, s
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
// film: 3104 x 4 samples spanning y/z in [-0.3071537409, -0.2187685003] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -577.1829893, 2194.936605>
  right <0, 194, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 23706.912
  pigment { function { max(0.002, min(0.98, 0.468913 * (1 + 0.0962507 * ((y / 23706.912) - -0.2629611206) / 0.04419262031 + 0 * sin(6.1145273 * ((y / 23706.912) - -0.2629611206) / 0.04419262031 + 1.48759)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -2104.341806, 9359.210012> + 280776 * <0.2377793383, -0.6061933029, -0.758940489> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, -2104.341806, 9359.210012>;  // mm
#declare V_0 = <-124.639034, 19.78302889, 49.6477023>;  // mm/s
#declare TC_0 = 1.4604943866541513;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.1317372467, 0.1317372467, 0.1317372467>] [0.925 rgb <0.1317372467, 0.1317372467, 0.1317372467>] [0.935 rgb <0.007159632975, 0.007159632975, 0.007159632975>] [1.0 rgb <0.007159632975, 0.007159632975, 0.007159632975>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.463 diffuse 0.537 phong 0.3652 phong_size 40 } }
  no_shadow
  rotate <29.91325267, 210.1092541, 339.6332884>
  transform { Axis_Rotate_Trans(<0.7040464803, -0.5036714853, -0.5006331875>, 94.519831 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
