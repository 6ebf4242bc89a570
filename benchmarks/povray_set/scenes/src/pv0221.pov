// validation scene pv0221 (seed 221)
#version 3.7;
#declare NS = 1;
#declare NLT = 87;
#declare LINES = array[87] { 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109 };
#declare LR = 12107.703962173313;  // line rate, Hz
#declare TAU = 3.620914148583512e-05;  // exposure, s
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
// film: 2096 x 4 samples spanning y/z in [-0.01382251118, 0.01220799989] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -4.062559107, 5032.55582>
  right <0, 131, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 30677.303
  pigment { function { max(0.002, min(0.98, 0.522506 * (1 + 0.0120779 * ((y / 30677.303) - -0.0008072556475) / 0.01301525554 + 0 * sin(22.509398 * ((y / 30677.303) - -0.0008072556475) / 0.01301525554 + 1.29004)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 26.7122747, 8705.66642> + 261170 * <0.3444011741, -0.7287494954, -0.5918716112> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, 26.7122747, 8705.66642>;  // mm
#declare V_0 = <-10165.22219, 850.0755119, -1383.901637>;  // mm/s
#declare TC_0 = 0.005451074803794023;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.100813446, 0.100813446, 0.09862184934>] [0.44 rgb <0.100813446, 0.100813446, 0.09862184934>] [0.46 rgb <0.07670588282, 0.09314285771, 0.01643697489>] [1.00 rgb <0.07670588282, 0.09314285771, 0.01643697489>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.5385 diffuse 0.4615 } }
  no_shadow
  rotate <239.896994, 243.4344592, 139.8355101>
  transform { Axis_Rotate_Trans(<0.6364146524, 0.7491054666, -0.1838950517>, 6815.4654 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
