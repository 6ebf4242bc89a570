// validation scene pv0066 (seed 66)
#version 3.7;
#declare NS = 1;
#declare NLT = 92;
#declare LINES = array[92] { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91 };
#declare LR = 4614.04833659915;  // line rate, Hz
#declare TAU = 2.3243964132231392e-05;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.234733 * sin(753.9822369 * T + 6.00888));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 480 x 4 samples spanning y/z in [-0.07466542725, 0.0604909947] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -6.292456847, 887.8601421>
  right <0, 120, 0>
  up <1, 0, 0>
  aperture 101.54161 blur_samples 19 focal_point <0, -28.04850792, 3957.6199> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 18510.14
  pigment { function { max(0.002, min(0.98, 0.0215013 * (1 + 0.121252 * ((y / 18510.14) - -0.007087216273) / 0.06757821097 + 0 * sin(19.534003 * ((y / 18510.14) - -0.007087216273) / 0.06757821097 + 1.29474)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 56.24094838, 5196.704566> + 155901 * <0.1024852425, 0.09338750041, -0.990341128> color rgb FL }


// ball 0: golf
#declare C0_0 = <0, 56.24094838, 5196.704566>;  // mm
#declare V_0 = <-2128.48173, 430.0129561, -504.5599626>;  // mm/s
#declare TC_0 = 0.008018988380878422;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.6783682584, 0.6783682584, 0.6783682584> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.5633 diffuse 0.4367 phong 0.35 phong_size 40 } }
  no_shadow
  rotate <180.1958397, 108.6434189, 152.1842019>
  transform { Axis_Rotate_Trans(<-0.7803759076, 0.1626458784, 0.6037878444>, 962.08341 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
