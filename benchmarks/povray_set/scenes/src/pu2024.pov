// validation scene pu2024 (seed 2024)
#version 3.7;
#declare NS = 2;
#declare NLT = 51;
#declare LINES = array[51] { 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63 };
#declare LR = 966.748272083849;  // line rate, Hz
#declare TAU = 0.000415410962896112;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.299969 * sin(753.9822369 * T + 3.93316));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 332 x 4 samples spanning y/z in [-0.02359324959, 0.02314644893] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -0.3967490123, 1775.955361>
  right <0, 83.00761819, 0>
  up <1, 0, 0>
  aperture 114.15092 blur_samples 19 focal_point <0, -3.146498109, 14084.572> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 36438.22
  pigment { function { max(0.002, min(0.98, 0.549542 * (1 + 0.336211 * ((y / 36438.22) - -0.0002234003292) / 0.02336984926 + 0.0748913 * sin(15.601572 * ((y / 36438.22) - -0.0002234003292) / 0.02336984926 + 2.35131)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 24.69227332, 10106.72113> + 303202 * <0.3717760829, -0.5020707482, -0.7808376963> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, 24.69227332, 10106.72113>;  // mm
#declare V_0 = <-4743.173415, -2194.548983, -1230.462037>;  // mm/s
#declare TC_0 = 0.03930702655210347;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.2270450519, 0.2270450519, 0.2270450519> }
  finish { ambient 1 diffuse 0 } }
  no_shadow
  rotate <208.1328793, 38.96214589, 54.78596982>
  transform { Axis_Rotate_Trans(<-0.5308239929, 0.7400344384, 0.4130071651>, 2704.0251 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
