// validation scene pv0074 (seed 74)
#version 3.7;
#declare NS = 2;
#declare NLT = 53;
#declare LINES = array[53] { 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65 };
#declare LR = 68.44765079901012;  // line rate, Hz
#declare TAU = 0.0027396324565778737;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.162928 * sin(753.9822369 * T + 0.755265));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 1680 x 4 samples spanning y/z in [0.003529458837, 0.05768959499] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 59.3731576, 1939.695369>
  right <0, 105.0541653, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 6856.4406
  pigment { function { max(0.002, min(0.98, 0.0358594 * (1 + 0.165533 * ((y / 6856.4406) - 0.03060952691) / 0.02708006808 + 0.0217507 * sin(18.232751 * ((y / 6856.4406) - 0.03060952691) / 0.02708006808 + 0.407096)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 36.19200171, 1257.703189> + 37731.1 * <0.5845877902, 0.1044145733, -0.8045835646> color rgb FL }
light_source { <0, 36.19200171, 1257.703189> + 37731.1 * <0.2097661869, -0.950263196, -0.230212956> color rgb FL * 0.674 }


// ball 0: pingpong
#declare C0_0 = <0, 36.19200171, 1257.703189>;  // mm
#declare V_0 = <-58.10387958, 24.43313944, -5.63097977>;  // mm/s
#declare TC_0 = 0.5697785029104901;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.847838171, 0.847838171, 0.847838171> }
  finish { ambient 0.203 diffuse 0.797 phong 0.3 phong_size 40 } }
  no_shadow
  rotate <334.4651282, 74.733853, 36.27290879>
  transform { Axis_Rotate_Trans(<0.4911778357, -0.07288830845, -0.8680043941>, 0 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
