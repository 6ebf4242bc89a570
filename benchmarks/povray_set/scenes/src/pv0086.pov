// validation scene pv0086 (seed 86)
#version 3.7;
#declare NS = 1;
#declare NLT = 71;
#declare LINES = array[71] { 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89 };
#declare LR = 116.02189083794701;  // line rate, Hz
#declare TAU = 0.0005979302378527301;  // exposure, s
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
// film: 552 x 4 samples spanning y/z in [-0.009740134153, 0.007485317256] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -9.032036116, 8011.325558>
  right <0, 137.9986991, 0>
  up <1, 0, 0>
  aperture 19.407551 blur_samples 19 focal_point <0, -8.031719829, 7124.055> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 53108.63
  pigment { function { max(0.002, min(0.98, 0.636784 * (1 + -0.166713 * ((y / 53108.63) - -0.001127408448) / 0.008612725705 + 0 * sin(13.246248 * ((y / 53108.63) - -0.001127408448) / 0.008612725705 + 4.28642)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -16.60751353, 11217.80131> + 336534 * <0.7272132672, -0.3769269108, -0.5736610218> color rgb FL }
light_source { <0, -16.60751353, 11217.80131> + 336534 * <0.5242740317, -0.6947365263, 0.4924204492> color rgb FL * 0.303 }


// ball 0: pingpong
#declare C0_0 = <0, -16.60751353, 11217.80131>;  // mm
#declare V_0 = <-72.10463414, -8.491045952, 8.150957586>;  // mm/s
#declare TC_0 = 0.46542940827799667;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.1815829073, 0.1815829073, 0.1815829073> }
  finish { ambient 0.1079 diffuse 0.8921 phong 0.3 phong_size 40 } }
  no_shadow
  rotate <157.9336902, 325.6798062, 128.3358861>
  transform { Axis_Rotate_Trans(<0.6778476741, 0.4905595624, -0.5476073835>, 22.682249 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
