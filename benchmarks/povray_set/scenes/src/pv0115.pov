// validation scene pv0115 (seed 115)
#version 3.7;
#declare NS = 2;
#declare NLT = 107;
#declare LINES = array[107] { 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136 };
#declare LR = 11290.378592038993;  // line rate, Hz
#declare TAU = 7.568298688215339e-05;  // exposure, s
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
// film: 644 x 4 samples spanning y/z in [-0.399554149, -0.346039216] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -1121.561076, 3008.506054>
  right <0, 161, 0>
  up <1, 0, 0>
  aperture 33.160615 blur_samples 19 focal_point <0, -4816.439592, 12919.749> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 19651.243
  pigment { function { max(0.002, min(0.98, 0.678557 * (1 + -0.203901 * ((y / 19651.243) - -0.3727966825) / 0.02675746651 + 0 * sin(12.767369 * ((y / 19651.243) - -0.3727966825) / 0.02675746651 + 0.971307)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -3433.027198, 9163.468835> + 274904 * <0.2883855029, 0.2997543588, -0.9093850263> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, -3433.027198, 9163.468835>;  // mm
#declare V_0 = <-7688.66215, -10115.60161, -6859.112354>;  // mm/s
#declare TC_0 = 0.007351392101104961;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.154468483, 0.154468483, 0.1511104725>] [0.44 rgb <0.154468483, 0.154468483, 0.1511104725>] [0.46 rgb <0.1175303675, 0.1427154463, 0.02518507876>] [1.00 rgb <0.1175303675, 0.1427154463, 0.02518507876>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.1159 diffuse 0.8841 } }
  no_shadow
  rotate <281.3160616, 67.30036288, 33.61761431>
  transform { Axis_Rotate_Trans(<0.9653459335, -0.2526196606, -0.06550218108>, 0 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
