// validation scene pu2014 (seed 2014)
#version 3.7;
#declare NS = 2;
#declare NLT = 69;
#declare LINES = array[69] { 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86 };
#declare LR = 127.11011631784162;  // line rate, Hz
#declare TAU = 0.004593350122120062;  // exposure, s
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
// film: 756 x 4 samples spanning y/z in [-0.06844599862, 0.09495874065] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 15.32941322, 1156.380823>
  right <0, 188.9581068, 0>
  up <1, 0, 0>
  aperture 43.019785 blur_samples 19 focal_point <0, 47.64916651, 3594.4352> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 8524.3799
  pigment { function { max(0.002, min(0.98, 0.0164427 * (1 + -0.141413 * ((y / 8524.3799) - 0.01325637101) / 0.08170236963 + 0.144939 * sin(12.013996 * ((y / 8524.3799) - 0.01325637101) / 0.08170236963 + 1.01862)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -55.33007507, 2294.419405> + 68832.6 * <0.600489211, 0.04649707465, -0.7982798566> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, -55.33007507, 2294.419405>;  // mm
#declare V_0 = <137.2248639, -9.363053485, -10.82747748>;  // mm/s
#declare TC_0 = 0.40909411073130375;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.6476754213, 0.7864630116, 0.1387875903> }
  finish { ambient 1 diffuse 0 } }
  no_shadow
  rotate <274.7042326, 265.0127924, 162.1163119>
  transform { Axis_Rotate_Trans(<-0.9239700631, 0.3068835835, 0.2282581621>, 0 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
