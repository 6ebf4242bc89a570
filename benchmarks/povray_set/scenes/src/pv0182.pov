// validation scene pv0182 (seed 182)
#version 3.7;
#declare NS = 1;
#declare NLT = 95;
#declare LINES = array[95] { 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120 };
#declare LR = 2286.3095904492316;  // line rate, Hz
#declare TAU = 1.5681618226364966e-05;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.088128 * sin(753.9822369 * T + 1.24233));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 756 x 4 samples spanning y/z in [-0.1344975035, 0.09584990751] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -15.85517201, 820.4997796>
  right <0, 189, 0>
  up <1, 0, 0>
  aperture 62.363908 blur_samples 19 focal_point <0, -91.14764732, 4716.8599> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 15128.344
  pigment { function { max(0.002, min(0.98, 0.274415 * (1 + -0.218165 * ((y / 15128.344) - -0.01932379802) / 0.1151737055 + 0.0703982 * sin(16.689002 * ((y / 15128.344) - -0.01932379802) / 0.1151737055 + 3.24466)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -429.3716778, 3197.874752> + 95936.2 * <-0.5513427989, 0.7637885638, -0.3356309697> color rgb FL }


// ball 0: pingpong
#declare C0_0 = <0, -429.3716778, 3197.874752>;  // mm
#declare V_0 = <-1107.313981, 159.989222, 535.7925605>;  // mm/s
#declare TC_0 = 0.031929184177395854;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.7250418919, 0.7250418919, 0.7250418919> }
  finish { ambient 0.3481 diffuse 0.6519 phong 0.3 phong_size 40 } }
  no_shadow
  rotate <155.079379, 147.429788, 331.9781211>
  transform { Axis_Rotate_Trans(<0.6644091169, 0.5580122262, -0.4971748996>, 0 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
