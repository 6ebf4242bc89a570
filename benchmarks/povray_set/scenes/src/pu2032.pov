// validation scene pu2032 (seed 2032)
#version 3.7;
#declare NS = 1;
#declare NLT = 51;
#declare LINES = array[51] { 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64 };
#declare LR = 11591.855340811284;  // line rate, Hz
#declare TAU = 4.991207473953463e-06;  // exposure, s
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
// film: 772 x 4 samples spanning y/z in [0.01869019646, 0.07989782564] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 155.4339591, 3153.201694>
  right <0, 193, 0>
  up <1, 0, 0>
  aperture 4.8904183 blur_samples 19 focal_point <0, 81.52497771, 1653.8516> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 8359.7844
  pigment { function { max(0.002, min(0.98, 0.220684 * (1 + -0.186641 * ((y / 8359.7844) - 0.04929401105) / 0.03060381459 + 0 * sin(6.8481763 * ((y / 8359.7844) - 0.04929401105) / 0.03060381459 + 0.134192)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 137.9851458, 2225.540161> + 66766.2 * <0.5491229196, 0.4908139666, -0.6764360054> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, 137.9851458, 2225.540161>;  // mm
#declare V_0 = <10506.16389, 1182.159563, 190.9385379>;  // mm/s
#declare TC_0 = 0.0033644312194522686;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.7572128491, 0.7572128491, 0.7572128491> }
  finish { ambient 1 diffuse 0 } }
  no_shadow
  rotate <205.4378512, 33.18466865, 106.9582324>
  transform { Axis_Rotate_Trans(<0.783627542, 0.3772656383, -0.4935570014>, 6983.4075 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
