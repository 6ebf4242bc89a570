// validation scene pv3660 (seed 3660)
#version 3.7;
#declare NS = 1;
#declare NLT = 96;
#declare LINES = array[96] { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95 };
#declare LR = 31827.800537441446;  // line rate, Hz
#declare TAU = 2.2941704934373574e-06;  // exposure, s
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
// film: 2480 x 4 samples spanning y/z in [-0.09260117913, 0.06682227564] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -12.53181361, 972.2534255>
  right <0, 155, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 9931.7451
  pigment { function { max(0.002, min(0.98, 0.125379 * (1 + -0.123194 * ((y / 9931.7451) - -0.01288945174) / 0.07971172738 + 0 * sin(16.468665 * ((y / 9931.7451) - -0.01288945174) / 0.07971172738 + 3.54038)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -110.769564, 3142.471083> + 94274.1 * <-0.5527316355, 0.1151687103, -0.8253628943> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, -110.769564, 3142.471083>;  // mm
#declare V_0 = <-43747.10603, 688.3117281, 1257.242976>;  // mm/s
#declare TC_0 = 0.000377028880330059;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.6469940388, 0.6469940388, 0.6469940388>] [0.925 rgb <0.6469940388, 0.6469940388, 0.6469940388>] [0.935 rgb <0.0351627195, 0.0351627195, 0.0351627195>] [1.0 rgb <0.0351627195, 0.0351627195, 0.0351627195>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.5892 diffuse 0.4108 } }
  no_shadow
  rotate <277.5958158, 148.0078289, 353.4076831>
  transform { Axis_Rotate_Trans(<0.4125036849, 0.774768295, 0.4791396446>, 793.30349 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
