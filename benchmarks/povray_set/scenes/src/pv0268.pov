// validation scene pv0268 (seed 268)
#version 3.7;
#declare NS = 1;
#declare NLT = 60;
#declare LINES = array[60] { 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95 };
#declare LR = 525.0321287715566;  // line rate, Hz
#declare TAU = 7.428351131934194e-05;  // exposure, s
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
// film: 444 x 4 samples spanning y/z in [0.2752316827, 0.4111171215] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 281.8393142, 821.2713784>
  right <0, 111.5988217, 0>
  up <1, 0, 0>
  aperture 124.35008 blur_samples 19 focal_point <0, 1522.87926, 4437.6249> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 21818.898
  pigment { function { max(0.002, min(0.98, 0.018217 * (1 + -0.267888 * ((y / 21818.898) - 0.3431744021) / 0.06794271944 + 0.189088 * sin(6.0579371 * ((y / 21818.898) - 0.3431744021) / 0.06794271944 + 5.05035)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 1578.672703, 5420.426178> + 162613 * <0.3500518026, -0.09005712433, -0.9323912536> color rgb FL }
light_source { <0, 1578.672703, 5420.426178> + 162613 * <-0.812075302, 0.5442516533, -0.2105322822> color rgb FL * 0.6399 }


// ball 0: golf
#declare C0_0 = <0, 1578.672703, 5420.426178>;  // mm
#declare V_0 = <-765.8266863, -811.7692388, 392.3986962>;  // mm/s
#declare TC_0 = 0.07428116845201495;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.7895654192, 0.7895654192, 0.7895654192> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.4978 diffuse 0.5022 phong 0.35 phong_size 40 } }
  no_shadow
  rotate <64.73198447, 154.8420523, 277.8841785>
  transform { Axis_Rotate_Trans(<-0.4348327299, -0.7256567205, 0.5332380528>, 151.69443 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
// ball 1: golf
#declare C0_1 = <0, 1890.963606, 5160.439401>;  // mm
#declare V_1 = <-1334.72095, -10.75945435, 16.91649107>;  // mm/s
#declare TC_1 = 0.15933596580702397;  // s
#declare P_1 = C0_1 + V_1 * (T - TC_1);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.7895654192, 0.7895654192, 0.7895654192> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.4978 diffuse 0.5022 phong 0.35 phong_size 40 } }
  no_shadow
  rotate <22.8994024, 87.1913355, 209.1548964>
  transform { Axis_Rotate_Trans(<-0.4348327299, -0.7256567205, 0.5332380528>, 151.69443 * (T - TC_1)) }
  scale 21.35
  translate P_1 }
#end
