// validation scene pv0033 (seed 33)
#version 3.7;
#declare NS = 1;
#declare NLT = 95;
#declare LINES = array[95] { 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120 };
#declare LR = 2871.464122302793;  // line rate, Hz
#declare TAU = 6.62377222678333e-05;  // exposure, s
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
// film: 380 x 4 samples spanning y/z in [-0.007205001741, 0.05219190481] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 35.97216888, 1599.228506>
  right <0, 94.9892261, 0>
  up <1, 0, 0>
  aperture 38.510915 blur_samples 19 focal_point <0, 125.5055752, 5579.6495> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 13164.876
  pigment { function { max(0.002, min(0.98, 0.12894 * (1 + -0.389242 * ((y / 13164.876) - 0.02249345153) / 0.02969845327 + 0 * sin(8.0180009 * ((y / 13164.876) - 0.02249345153) / 0.02969845327 + 5.1983)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -7.044456797, 3533.443323> + 106003 * <-0.2240743424, -0.02232624061, -0.9743162875> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, -7.044456797, 3533.443323>;  // mm
#declare V_0 = <2198.567415, 691.5504529, 295.3097957>;  // mm/s
#declare TC_0 = 0.02542257081779489;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.7713747041, 0.7713747041, 0.7546056888>] [0.44 rgb <0.7713747041, 0.7713747041, 0.7546056888>] [0.46 rgb <0.5869155357, 0.7126831505, 0.1257676148>] [1.00 rgb <0.5869155357, 0.7126831505, 0.1257676148>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.5867 diffuse 0.4133 phong 0.5899 phong_size 40 } }
  no_shadow
  rotate <38.68169198, 104.3998307, 195.024148>
  transform { Axis_Rotate_Trans(<0.2567024507, -0.9412998096, 0.2192225358>, 1982.699 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
