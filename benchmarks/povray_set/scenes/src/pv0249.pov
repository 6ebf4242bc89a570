// validation scene pv0249 (seed 249)
#version 3.7;
#declare NS = 1;
#declare NLT = 53;
#declare LINES = array[53] { 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65 };
#declare LR = 28284.663268928216;  // line rate, Hz
#declare TAU = 1.282716465596015e-05;  // exposure, s
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
// film: 512 x 4 samples spanning y/z in [0.1353055596, 0.2879901659] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 177.4306336, 838.3294366>
  right <0, 128, 0>
  up <1, 0, 0>
  aperture 86.663687 blur_samples 19 focal_point <0, 662.7250669, 3131.2627> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 20448.989
  pigment { function { max(0.002, min(0.98, 0.0182183 * (1 + 0.0463175 * ((y / 20448.989) - 0.2116478628) / 0.07634230316 + 0.15771 * sin(8.9762485 * ((y / 20448.989) - 0.2116478628) / 0.07634230316 + 6.07171)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 866.593824, 4059.286893> + 121779 * <-0.5591722538, 0.2751096109, -0.7820748638> color rgb FL }
light_source { <0, 866.593824, 4059.286893> + 121779 * <-0.9572191322, -0.241186041, -0.1598775362> color rgb FL * 0.3984 }


// ball 0: golf
#declare C0_0 = <0, 866.593824, 4059.286893>;  // mm
#declare V_0 = <27992.05474, 2529.997891, -5401.097885>;  // mm/s
#declare TC_0 = 0.0013788391125321613;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.666740825, 0.666740825, 0.666740825> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.5605 diffuse 0.4395 phong 0.5199 phong_size 40 } }
  no_shadow
  rotate <294.9549797, 110.6301829, 216.9245418>
  transform { Axis_Rotate_Trans(<-0.732292955, 0.4672165011, 0.4954349293>, 15335.128 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
