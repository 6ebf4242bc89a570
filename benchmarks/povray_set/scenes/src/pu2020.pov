// validation scene pu2020 (seed 2020)
#version 3.7;
#declare NS = 1;
#declare NLT = 53;
#declare LINES = array[53] { 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65 };
#declare LR = 121.5706914126572;  // line rate, Hz
#declare TAU = 0.0009064409063413198;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.347673 * sin(753.9822369 * T + 2.33146));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 560 x 4 samples spanning y/z in [-0.3972722937, -0.2723325325] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -375.1594959, 1120.54>
  right <0, 140, 0>
  up <1, 0, 0>
  aperture 9.0282109 blur_samples 19 focal_point <0, -594.2837191, 1775.0282> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 5594.1997
  pigment { function { max(0.002, min(0.98, 0.632692 * (1 + -0.145518 * ((y / 5594.1997) - -0.3348024131) / 0.06246988061 + 0.185718 * sin(10.405209 * ((y / 5594.1997) - -0.3348024131) / 0.06246988061 + 4.41391)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -403.9787082, 1141.651936> + 34249.6 * <0.7490775065, 0.05748775033, -0.6599833694> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, -403.9787082, 1141.651936>;  // mm
#declare V_0 = <186.6888559, 5.45816426, 8.384595078>;  // mm/s
#declare TC_0 = 0.3208010051338703;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.1682475094, 0.1645086758, 0.1532921752> }
  finish { ambient 1 diffuse 0 } }
  no_shadow
  rotate <292.1417487, 164.9248415, 25.43991754>
  transform { Axis_Rotate_Trans(<0.08214320617, 0.1239254077, 0.98888573>, 116.74877 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
