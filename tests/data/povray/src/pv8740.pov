// validation scene pv8740 (seed 8740)
#version 3.7;
#declare NS = 3;
#declare NLT = 85;
#declare LINES = array[85] { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84 };
#declare LR = 83207.67812660396;  // line rate, Hz
#declare TAU = 1.1125050083790933e-05;  // exposure, s
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
// film: 2016 x 4 samples spanning y/z in [-0.06608597863, -0.04620671623] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -355.8703354, 6338.263337>
  right <0, 126, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 20904.011
  pigment { function { max(0.002, min(0.98, 0.139877 * (1 + 0.303419 * ((y / 20904.011) - -0.05614634743) / 0.009939631198 + 0 * sin(17.334635 * ((y / 20904.011) - -0.05614634743) / 0.009939631198 + 4.26749)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -337.8328099, 5981.170193> + 179435 * <-0.8992050533, -0.02357167137, -0.4368920329> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, -337.8328099, 5981.170193>;  // mm
#declare V_0 = <48133.07844, -1277.306467, -3252.354439>;  // mm/s
#declare TC_0 = 0.00021632619014572485;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.8445124588, 0.8257455153, 0.7694446847>] [0.5 rgb <0.8445124588, 0.8257455153, 0.7694446847>] [0.5 rgb <0.7037603824, 0.07506777412, 0.05630083059>] [1.0 rgb <0.7037603824, 0.07506777412, 0.05630083059>] } }
  finish { ambient 0.5474 diffuse 0.4526 phong 0.1 phong_size 40 } }
  no_shadow
  rotate <5.861334547, 21.65676781, 288.550879>
  transform { Axis_Rotate_Trans(<0.5910424182, 0.6724652098, 0.4454878242>, 2283.7025 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
