// validation scene pv0216 (seed 216)
#version 3.7;
#declare NS = 1;
#declare NLT = 127;
#declare LINES = array[127] { 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162 };
#declare LR = 257.8476286463453;  // line rate, Hz
#declare TAU = 0.00039636186250040776;  // exposure, s
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
// film: 788 x 4 samples spanning y/z in [-0.4149044828, -0.1716600305] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -237.5248603, 809.8848631>
  right <0, 197, 0>
  up <1, 0, 0>
  aperture 28.352996 blur_samples 19 focal_point <0, -714.9725758, 2437.831> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 4897.3511
  pigment { function { max(0.002, min(0.98, 0.617404 * (1 + 0.342083 * ((y / 4897.3511) - -0.2932822566) / 0.1216222262 + 0.0327495 * sin(6.5764262 * ((y / 4897.3511) - -0.2932822566) / 0.1216222262 + 5.74512)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -451.2445282, 1558.957745> + 46768.7 * <0.241136534, 0.3308400777, -0.9123584904> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, -451.2445282, 1558.957745>;  // mm
#declare V_0 = <-144.702236, -11.63935427, -75.86977375>;  // mm/s
#declare TC_0 = 0.3839476846063413;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.2265479444, 0.2265479444, 0.2216229891>] [0.44 rgb <0.2265479444, 0.2265479444, 0.2216229891>] [0.46 rgb <0.1723734359, 0.2093106008, 0.03693716484>] [1.00 rgb <0.1723734359, 0.2093106008, 0.03693716484>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.2299 diffuse 0.7701 } }
  no_shadow
  rotate <348.8574905, 284.0302131, 276.9572048>
  transform { Axis_Rotate_Trans(<-0.8976849924, 0.08245779911, -0.4328537464>, 0 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
