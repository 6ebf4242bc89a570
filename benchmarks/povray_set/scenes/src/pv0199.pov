// validation scene pv0199 (seed 199)
#version 3.7;
#declare NS = 1;
#declare NLT = 33;
#declare LINES = array[33] { 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40 };
#declare LR = 34.438721479915735;  // line rate, Hz
#declare TAU = 0.002311537616457791;  // exposure, s
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
// film: 3040 x 4 samples spanning y/z in [-0.01576663334, 0.02175860819] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 15.16945893, 5063.25855>
  right <0, 190, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 46550.833
  pigment { function { max(0.002, min(0.98, 0.0112671 * (1 + 0.287629 * ((y / 46550.833) - 0.002995987423) / 0.01876262076 + 0.172534 * sin(18.448196 * ((y / 46550.833) - 0.002995987423) / 0.01876262076 + 4.11777)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -165.0213058, 13245.75526> + 397373 * <0.7907595598, 0.5532718787, -0.2618960611> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, -165.0213058, 13245.75526>;  // mm
#declare V_0 = <83.20881456, -8.158367221, -44.80052481>;  // mm/s
#declare TC_0 = 0.6968899822252845;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.6519041287, 0.6519041287, 0.6377322999>] [0.44 rgb <0.6519041287, 0.6519041287, 0.6377322999>] [0.46 rgb <0.496014011, 0.6023027276, 0.1062887166>] [1.00 rgb <0.496014011, 0.6023027276, 0.1062887166>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.1924 diffuse 0.8076 phong 0.5784 phong_size 40 } }
  no_shadow
  rotate <46.38362562, 251.980246, 97.49523836>
  transform { Axis_Rotate_Trans(<0.01753634984, 0.2828238733, 0.9590115396>, 10.207361 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
