// validation scene pv4276 (seed 4276)
#version 3.7;
#declare NS = 1;
#declare NLT = 88;
#declare LINES = array[88] { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87 };
#declare LR = 186.18746051453073;  // line rate, Hz
#declare TAU = 0.0003577742055597468;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.226386 * sin(753.9822369 * T + 3.97696));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 2368 x 4 samples spanning y/z in [-0.03412501457, 0.05540852899] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 17.59909416, 1653.77708>
  right <0, 148.0685223, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 4598.5105
  pigment { function { max(0.002, min(0.98, 0.0138059 * (1 + -0.0393517 * ((y / 4598.5105) - 0.01064175721) / 0.04476677178 + 0.0460268 * sin(21.780082 * ((y / 4598.5105) - 0.01064175721) / 0.04476677178 + 4.70788)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 2.055544133, 1038.594993> + 31157.8 * <0.2241087259, -0.3139192864, -0.9226212444> color rgb FL }
light_source { <0, 2.055544133, 1038.594993> + 31157.8 * <0.8764090142, -0.2359921138, -0.419779659> color rgb FL * 0.6356 }


// ball 0: golf
#declare C0_0 = <0, 2.055544133, 1038.594993>;  // mm
#declare V_0 = <-75.55691592, 62.23929915, 10.11018662>;  // mm/s
#declare TC_0 = 0.171869791400386;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.9050924916, 0.9050924916, 0.9050924916> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.5799 diffuse 0.4201 phong 0.5218 phong_size 40 } }
  no_shadow
  rotate <238.491083, 253.0863279, 133.0052093>
  transform { Axis_Rotate_Trans(<-0.4174080787, -0.8669990677, -0.2721821312>, 23.741183 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
