// validation scene pu2006 (seed 2006)
#version 3.7;
#declare NS = 1;
#declare NLT = 97;
#declare LINES = array[97] { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96 };
#declare LR = 15287.66923385078;  // line rate, Hz
#declare TAU = 4.022295245152584e-06;  // exposure, s
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
// film: 340 x 4 samples spanning y/z in [-0.03286721825, 0.02963678402] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -2.196201232, 1359.694131>
  right <0, 84.98632508, 0>
  up <1, 0, 0>
  aperture 144.82229 blur_samples 19 focal_point <0, -35.91592282, 22235.972> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 33370.458
  pigment { function { max(0.002, min(0.98, 0.137153 * (1 + 0.0132362 * ((y / 33370.458) - -0.001615217115) / 0.03125200114 + 0.0829081 * sin(11.689628 * ((y / 33370.458) - -0.001615217115) / 0.03125200114 + 5.08852)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -273.1793222, 13980.70566> + 419421 * <-0.03145408968, 0.5219788363, -0.8523782815> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, -273.1793222, 13980.70566>;  // mm
#declare V_0 = <26837.8801, 3712.958888, -1262.171756>;  // mm/s
#declare TC_0 = 0.0018969536530648269;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.8880305898, 0.8880305898, 0.8880305898> }
  finish { ambient 1 diffuse 0 } }
  no_shadow
  rotate <74.80693307, 10.81333084, 110.7781172>
  transform { Axis_Rotate_Trans(<-0.0002107525501, 0.3211651621, -0.9470231751>, 2025.6792 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
