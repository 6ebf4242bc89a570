// validation scene pv0104 (seed 104)
#version 3.7;
#declare NS = 1;
#declare NLT = 51;
#declare LINES = array[51] { 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64 };
#declare LR = 52.16262304363261;  // line rate, Hz
#declare TAU = 0.0030644103051981043;  // exposure, s
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
// film: 536 x 4 samples spanning y/z in [0.2147191772, 0.2974207577] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 393.685222, 1537.412708>
  right <0, 127.1464608, 0>
  up <1, 0, 0>
  aperture 10.971319 blur_samples 19 focal_point <0, 349.4653944, 1364.7262> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 5753.2575
  pigment { function { max(0.002, min(0.98, 0.822974 * (1 + -0.34262 * ((y / 5753.2575) - 0.2560699675) / 0.04135079024 + 0.130334 * sin(15.585165 * ((y / 5753.2575) - 0.2560699675) / 0.04135079024 + 5.18268)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 271.243975, 1083.984117> + 32519.5 * <0.4654547577, 0.6291432837, -0.6225195556> color rgb FL }
light_source { <0, 271.243975, 1083.984117> + 32519.5 * <-0.7337678632, -0.6623557548, 0.1512269056> color rgb FL * 0.4786 }


// ball 0: pingpong
#declare C0_0 = <0, 271.243975, 1083.984117>;  // mm
#declare V_0 = <44.75547658, -34.18358275, -3.813451474>;  // mm/s
#declare TC_0 = 0.7476617877781485;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.1364974571, 0.06142385567, 0.006824872853> }
  finish { ambient 0.4903 diffuse 0.5097 phong 0.3 phong_size 40 } }
  no_shadow
  rotate <201.9483098, 313.6946526, 183.8455837>
  transform { Axis_Rotate_Trans(<0.7840730552, 0.07286820125, -0.6163762401>, 35.204098 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
