// validation scene pv3422 (seed 3422)
#version 3.7;
#declare NS = 1;
#declare NLT = 77;
#declare LINES = array[77] { 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106 };
#declare LR = 13931.592389710784;  // line rate, Hz
#declare TAU = 6.140640734017064e-06;  // exposure, s
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
// film: 2384 x 4 samples spanning y/z in [-0.06295021977, 0.05808274149] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -2.997906083, 1231.81077>
  right <0, 149.0897052, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 12116.777
  pigment { function { max(0.002, min(0.98, 0.121276 * (1 + -0.27515 * ((y / 12116.777) - -0.00243373914) / 0.06051648063 + 0.00594361 * sin(4.8650769 * ((y / 12116.777) - -0.00243373914) / 0.06051648063 + 0.421233)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 16.43889735, 2593.761745> + 77812.9 * <0.2658771254, -0.3028232086, -0.9152089699> color rgb FL }


// ball 0: pingpong
#declare C0_0 = <0, 16.43889735, 2593.761745>;  // mm
#declare V_0 = <5675.572066, 5039.152372, -1995.515504>;  // mm/s
#declare TC_0 = 0.005957682200155374;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.7754721839, 0.7754721839, 0.7754721839> }
  finish { ambient 0.3532 diffuse 0.6468 phong 0.5843 phong_size 40 } }
  no_shadow
  rotate <334.5876259, 124.4543324, 68.61706792>
  transform { Axis_Rotate_Trans(<0.6510232706, -0.4741287194, 0.5927652644>, 5083.6119 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
