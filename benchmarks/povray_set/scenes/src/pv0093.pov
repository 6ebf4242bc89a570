// validation scene pv0093 (seed 93)
#version 3.7;
#declare NS = 1;
#declare NLT = 73;
#declare LINES = array[73] { 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91 };
#declare LR = 50642.807655520824;  // line rate, Hz
#declare TAU = 2.051666041057906e-06;  // exposure, s
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
// film: 636 x 4 samples spanning y/z in [-0.07052729371, 0.05049436336] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -13.15977653, 1313.814435>
  right <0, 159, 0>
  up <1, 0, 0>
  aperture 14.394649 blur_samples 19 focal_point <0, -75.31635575, 7519.255> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 10334.485
  pigment { function { max(0.002, min(0.98, 0.0225599 * (1 + -0.353172 * ((y / 10334.485) - -0.01001646517) / 0.06051082853 + 0 * sin(6.2299017 * ((y / 10334.485) - -0.01001646517) / 0.06051082853 + 3.02542)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 128.4272538, 4811.785539> + 144354 * <-0.26769844, -0.4612324525, -0.8459327219> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, 128.4272538, 4811.785539>;  // mm
#declare V_0 = <66186.03236, 734.947066, -2592.018335>;  // mm/s
#declare TC_0 = 0.0010860377326256747;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.3130481199, 0.4288312414, 0.5271010846> }
  finish { ambient 0.3862 diffuse 0.6138 phong 0.4164 phong_size 40 } }
  no_shadow
  rotate <103.7957393, 179.5870042, 289.1981671>
  transform { Axis_Rotate_Trans(<0.1701755118, 0.3395276787, -0.925073646>, 0 * (T - TC_0)) }
  scale 42.56704961
  translate P_0 }
#end
