// validation scene pv0126 (seed 126)
#version 3.7;
#declare NS = 2;
#declare NLT = 49;
#declare LINES = array[49] { 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61 };
#declare LR = 57.9931842328158;  // line rate, Hz
#declare TAU = 0.0075485202552752735;  // exposure, s
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
// film: 2800 x 4 samples spanning y/z in [-0.06500980713, 0.08628411953] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 12.29610823, 1155.958228>
  right <0, 174.8894593, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 42392.137
  pigment { function { max(0.002, min(0.98, 0.0177295 * (1 + -0.0620966 * ((y / 42392.137) - 0.0106371562) / 0.07564696333 + 0 * sin(4.1262785 * ((y / 42392.137) - 0.0106371562) / 0.07564696333 + 0.132644)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 76.24655672, 7397.085661> + 221913 * <-0.007209503821, 0.2256713435, -0.9741768155> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, 76.24655672, 7397.085661>;  // mm
#declare V_0 = <290.7536361, 28.42303925, -150.8774464>;  // mm/s
#declare TC_0 = 0.638006008627878;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.7309526942, 0.7309526942, 0.7309526942>] [0.925 rgb <0.7309526942, 0.7309526942, 0.7309526942>] [0.935 rgb <0.0397256899, 0.0397256899, 0.0397256899>] [1.0 rgb <0.0397256899, 0.0397256899, 0.0397256899>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.1861 diffuse 0.8139 phong 0.6442 phong_size 40 } }
  no_shadow
  rotate <258.3178393, 171.9458811, 125.3781342>
  transform { Axis_Rotate_Trans(<-0.9918232306, -0.1083230783, 0.06747436475>, 97.148651 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
