// validation scene pv3479 (seed 3479)
#version 3.7;
#declare NS = 1;
#declare NLT = 95;
#declare LINES = array[95] { 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121 };
#declare LR = 46.848098957331956;  // line rate, Hz
#declare TAU = 0.009258185240633264;  // exposure, s
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
// film: 2928 x 4 samples spanning y/z in [0.2080145667, 0.4312441583] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 285.1370419, 892.086508>
  right <0, 199.1401068, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 27390.237
  pigment { function { max(0.002, min(0.98, 0.0519061 * (1 + 0.0610971 * ((y / 27390.237) - 0.3196293625) / 0.1116147958 + 0.167957 * sin(17.91365 * ((y / 27390.237) - 0.3196293625) / 0.1116147958 + 4.31815)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 1889.973009, 8771.409985> + 263142 * <-0.2813852222, -0.3571166714, -0.8906683107> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, 1889.973009, 8771.409985>;  // mm
#declare V_0 = <118.3660766, -67.5132099, -5.598752711>;  // mm/s
#declare TC_0 = 1.579573166189674;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.7827006993, 0.7827006993, 0.7827006993>] [0.925 rgb <0.7827006993, 0.7827006993, 0.7827006993>] [0.935 rgb <0.04253808148, 0.04253808148, 0.04253808148>] [1.0 rgb <0.04253808148, 0.04253808148, 0.04253808148>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.1643 diffuse 0.8357 } }
  no_shadow
  rotate <26.70234176, 318.8553448, 143.6741724>
  transform { Axis_Rotate_Trans(<0.1317667793, 0.9367464402, -0.3242585739>, 20.22058 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
