// validation scene pv0041 (seed 41)
#version 3.7;
#declare NS = 1;
#declare NLT = 47;
#declare LINES = array[47] { 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58 };
#declare LR = 5383.029478975196;  // line rate, Hz
#declare TAU = 3.603854867104576e-05;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.242685 * sin(628.3185307 * T + 3.86646));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 476 x 4 samples spanning y/z in [-0.08361743225, 0.02325954552] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -33.6021315, 1113.429688>
  right <0, 119, 0>
  up <1, 0, 0>
  aperture 9.9823933 blur_samples 19 focal_point <0, -62.91358405, 2084.6848> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 6820.326
  pigment { function { max(0.002, min(0.98, 0.0160288 * (1 + 0.166208 * ((y / 6820.326) - -0.03017894337) / 0.05343848888 + 0 * sin(14.865764 * ((y / 6820.326) - -0.03017894337) / 0.05343848888 + 0.233339)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -38.31867906, 1323.20466> + 39696.1 * <-0.3916831026, 0.6582810278, -0.6428455768> color rgb FL }
light_source { <0, -38.31867906, 1323.20466> + 39696.1 * <0.1772013969, 0.9743570372, 0.1386651686> color rgb FL * 0.411 }


// ball 0: golf
#declare C0_0 = <0, -38.31867906, 1323.20466>;  // mm
#declare V_0 = <-5454.644339, -897.0547162, 175.1846603>;  // mm/s
#declare TC_0 = 0.006501914978675388;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.6938456745, 0.6938456745, 0.6938456745> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.1918 diffuse 0.8082 phong 0.35 phong_size 40 } }
  no_shadow
  rotate <153.0638623, 141.2548713, 182.235916>
  transform { Axis_Rotate_Trans(<0.3447171964, 0.8914758817, -0.2940081748>, 1783.8269 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
