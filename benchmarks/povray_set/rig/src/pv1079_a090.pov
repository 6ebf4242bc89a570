// validation scene pv1079_a090 (seed 1079)
#version 3.7;
#declare NS = 1;
#declare NLT = 129;
#declare LINES = array[129] { 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164 };
#declare LR = 6690.154057434236;  // line rate, Hz
#declare TAU = 1.0773188937170318e-05;  // exposure, s
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
// film: 1424 x 4 samples spanning y/z in [-0.1273551133, -0.07257022352] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -162.3929067, 1624.535532>
  right <0, 89, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 9615.7375
  pigment { function { max(0.002, min(0.98, 0.498332 * (1 + 0.162619 * ((y / 9615.7375) - -0.09996266839) / 0.02739244487 + 0 * sin(4.2323092 * ((y / 9615.7375) - -0.09996266839) / 0.02739244487 + 0.991555)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -184.3411025, 1829.539322> + 54886.2 * <-0.4620747891, -0.1440636984, 0.8750614493> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, -184.3411025, 1829.539322>;  // mm
#declare V_0 = <-3999.054682, -2012.306839, 608.630352>;  // mm/s
#declare TC_0 = 0.014947338901542626;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.1538800981, 0.1504605404, 0.1402018672>] [0.5 rgb <0.1538800981, 0.1504605404, 0.1402018672>] [0.5 rgb <0.1282334151, 0.01367823095, 0.01025867321>] [1.0 rgb <0.1282334151, 0.01367823095, 0.01025867321>] } }
  finish { ambient 0.1276 diffuse 0.8724 phong 0.1 phong_size 40 } }
  no_shadow
  rotate <266.0295417, 151.5941778, 342.6307977>
  transform { Axis_Rotate_Trans(<0.6376292457, 0.7601919645, 0.1246479929>, 1239.9151 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
