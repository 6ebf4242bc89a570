// validation scene pv0257 (seed 257)
#version 3.7;
#declare NS = 1;
#declare NLT = 57;
#declare LINES = array[57] { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56 };
#declare LR = 372.0773083626279;  // line rate, Hz
#declare TAU = 0.00038463781333773127;  // exposure, s
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
// film: 1504 x 4 samples spanning y/z in [0.05468062381, 0.09340202567] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 179.6359812, 2426.15839>
  right <0, 93.94425398, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 27265.999
  pigment { function { max(0.002, min(0.98, 0.020942 * (1 + 0.285472 * ((y / 27265.999) - 0.07404132474) / 0.01936070093 + 0.239667 * sin(11.151955 * ((y / 27265.999) - 0.07404132474) / 0.01936070093 + 4.72316)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 706.7866164, 9449.832188> + 283495 * <0.6635118952, -0.4105785439, -0.6254416234> color rgb FL }
light_source { <0, 706.7866164, 9449.832188> + 283495 * <0.1835533832, -0.6307195283, -0.7539900743> color rgb FL * 0.3874 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, 706.7866164, 9449.832188>;  // mm
#declare V_0 = <1078.995364, -229.1581012, -57.86077755>;  // mm/s
#declare TC_0 = 0.0430018161290458;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.7765477871, 0.7765477871, 0.7765477871>] [0.925 rgb <0.7765477871, 0.7765477871, 0.7765477871>] [0.935 rgb <0.04220368408, 0.04220368408, 0.04220368408>] [1.0 rgb <0.04220368408, 0.04220368408, 0.04220368408>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.4214 diffuse 0.5786 phong 0.2417 phong_size 40 } }
  no_shadow
  rotate <120.0356698, 24.03232634, 111.4646447>
  transform { Axis_Rotate_Trans(<0.4821929884, 0.8648820792, -0.1395310399>, 85.533753 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
