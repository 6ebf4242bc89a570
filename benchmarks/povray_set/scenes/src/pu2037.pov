// validation scene pu2037 (seed 2037)
#version 3.7;
#declare NS = 1;
#declare NLT = 33;
#declare LINES = array[33] { 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39 };
#declare LR = 54.12320677131419;  // line rate, Hz
#declare TAU = 0.0028636948919174322;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.200605 * sin(753.9822369 * T + 4.57254));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 420 x 4 samples spanning y/z in [0.0770433235, 0.09208260087] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 588.7395809, 6962.144723>
  right <0, 104.7056255, 0>
  up <1, 0, 0>
  aperture 3.7833941 blur_samples 19 focal_point <0, 539.7545758, 6382.8721> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 39128.739
  pigment { function { max(0.002, min(0.98, 0.0654079 * (1 + -0.206143 * ((y / 39128.739) - 0.08456296219) / 0.007519638682 + 0.0269493 * sin(6.4960698 * ((y / 39128.739) - 0.08456296219) / 0.007519638682 + 3.2329)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 873.8131051, 10383.80785> + 311514 * <0.08372887199, -0.909259646, -0.4077209489> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, 873.8131051, 10383.80785>;  // mm
#declare V_0 = <83.87282217, 6.220858374, 4.078315656>;  // mm/s
#declare TC_0 = 0.42495634261254117;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.7062189988, 0.7062189988, 0.7062189988> }
  finish { ambient 1 diffuse 0 } }
  no_shadow
  rotate <216.1467944, 122.8805828, 124.3300893>
  transform { Axis_Rotate_Trans(<0.1156108691, -0.6708972718, 0.732482749>, 34.857193 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
