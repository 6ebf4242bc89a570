// validation scene pv0042 (seed 42)
#version 3.7;
#declare NS = 1;
#declare NLT = 104;
#declare LINES = array[104] { 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132 };
#declare LR = 171.655387573476;  // line rate, Hz
#declare TAU = 0.0012218261058307312;  // exposure, s
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
// film: 2176 x 4 samples spanning y/z in [0.1912954488, 0.2302963167] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 735.0667191, 3487.10188>
  right <0, 136, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 34385.178
  pigment { function { max(0.002, min(0.98, 0.0716866 * (1 + 0.166399 * ((y / 34385.178) - 0.2107958827) / 0.01950043398 + 0 * sin(14.275166 * ((y / 34385.178) - 0.2107958827) / 0.01950043398 + 3.51497)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 1919.139654, 9552.134322> + 286564 * <0.587292684, -0.5155649842, -0.6239231125> color rgb FL }
light_source { <0, 1919.139654, 9552.134322> + 286564 * <-0.4676405046, -0.7873182452, -0.401798879> color rgb FL * 0.4209 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, 1919.139654, 9552.134322>;  // mm
#declare V_0 = <168.3263076, 64.78266293, -86.26221064>;  // mm/s
#declare TC_0 = 0.38449128182329334;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.7647434155, 0.7647434155, 0.7481185586>] [0.44 rgb <0.7647434155, 0.7647434155, 0.7481185586>] [0.46 rgb <0.5818699901, 0.7065564165, 0.1246864264>] [1.00 rgb <0.5818699901, 0.7065564165, 0.1246864264>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.4986 diffuse 0.5014 } }
  no_shadow
  rotate <69.65445506, 8.7390227, 337.4885526>
  transform { Axis_Rotate_Trans(<-0.98809169, -0.03465633503, -0.1499124768>, 126.11253 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
// ball 1: tennis
#declare C0_1 = <0, 1933.492192, 8616.590478>;  // mm
#declare V_1 = <227.2931064, -5.562553602, 11.35487121>;  // mm/s
#declare TC_1 = 0.6052986854418068;  // s
#declare P_1 = C0_1 + V_1 * (T - TC_1);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.7647434155, 0.7647434155, 0.7481185586>] [0.44 rgb <0.7647434155, 0.7647434155, 0.7481185586>] [0.46 rgb <0.5818699901, 0.7065564165, 0.1246864264>] [1.00 rgb <0.5818699901, 0.7065564165, 0.1246864264>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.4986 diffuse 0.5014 } }
  no_shadow
  rotate <52.64464763, 216.0075422, 168.7656403>
  transform { Axis_Rotate_Trans(<-0.98809169, -0.03465633503, -0.1499124768>, 126.11253 * (T - TC_1)) }
  scale 33.5
  translate P_1 }
#end
