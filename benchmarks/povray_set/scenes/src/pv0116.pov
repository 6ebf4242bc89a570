// validation scene pv0116 (seed 116)
#version 3.7;
#declare NS = 1;
#declare NLT = 95;
#declare LINES = array[95] { 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120 };
#declare LR = 184.92093142884113;  // line rate, Hz
#declare TAU = 0.0007692929304119577;  // exposure, s
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
// film: 1712 x 4 samples spanning y/z in [-0.2840546913, -0.2234324611] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -447.8647942, 1765.029093>
  right <0, 107, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 9945.7495
  pigment { function { max(0.002, min(0.98, 0.688831 * (1 + -0.0710845 * ((y / 9945.7495) - -0.2537435762) / 0.0303111151 + 0.199859 * sin(4.0013338 * ((y / 9945.7495) - -0.2537435762) / 0.0303111151 + 2.18068)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -614.9525961, 2413.350762> + 72400.5 * <-0.6027006556, 0.2801257928, -0.7471823472> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, -614.9525961, 2413.350762>;  // mm
#declare V_0 = <140.6170343, 10.32436097, 13.13869712>;  // mm/s
#declare TC_0 = 0.394763315520563;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.202255499, 0.202255499, 0.1978586404>] [0.44 rgb <0.202255499, 0.202255499, 0.1978586404>] [0.46 rgb <0.1538900536, 0.1868664937, 0.03297644006>] [1.00 rgb <0.1538900536, 0.1868664937, 0.03297644006>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.5337 diffuse 0.4663 } }
  no_shadow
  rotate <249.9299129, 267.9447436, 215.7787562>
  transform { Axis_Rotate_Trans(<0.8778771431, -0.02881053651, 0.4780184877>, 0 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
