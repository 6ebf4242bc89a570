// validation scene pv0151 (seed 151)
#version 3.7;
#declare NS = 1;
#declare NLT = 75;
#declare LINES = array[75] { 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95 };
#declare LR = 61933.320526351985;  // line rate, Hz
#declare TAU = 9.167304891106398e-07;  // exposure, s
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
// film: 1232 x 4 samples spanning y/z in [-0.004909579183, 0.005476511441] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 2.101550307, 7413.761615>
  right <0, 77, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 72466.227
  pigment { function { max(0.002, min(0.98, 0.205041 * (1 + 0.0957712 * ((y / 72466.227) - 0.0002834661291) / 0.005193045312 + 0.122838 * sin(12.287563 * ((y / 72466.227) - 0.0002834661291) / 0.005193045312 + 0.987957)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -5.316825959, 13865.03309> + 415951 * <0.3591209616, 0.07813222696, -0.9300147795> color rgb FL }
light_source { <0, -5.316825959, 13865.03309> + 415951 * <0.3643798373, 0.662024985, -0.6549429391> color rgb FL * 0.2746 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, -5.316825959, 13865.03309>;  // mm
#declare V_0 = <59743.33096, -12479.23316, 1994.507269>;  // mm/s
#declare TC_0 = 0.0009364910440305167;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.7461727562, 0.7461727562, 0.7299516093>] [0.44 rgb <0.7461727562, 0.7461727562, 0.7299516093>] [0.46 rgb <0.5677401406, 0.6893987421, 0.1216586016>] [1.00 rgb <0.5677401406, 0.6893987421, 0.1216586016>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.1502 diffuse 0.8498 phong 0.7754 phong_size 40 } }
  no_shadow
  rotate <249.7507356, 349.4137482, 308.1543304>
  transform { Axis_Rotate_Trans(<-0.6670913196, 0.248249333, 0.7023969248>, 7151.2072 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
