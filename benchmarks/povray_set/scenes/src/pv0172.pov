// validation scene pv0172 (seed 172)
#version 3.7;
#declare NS = 2;
#declare NLT = 29;
#declare LINES = array[29] { 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35 };
#declare LR = 235.32552119762036;  // line rate, Hz
#declare TAU = 0.0005428142364513977;  // exposure, s
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
// film: 2400 x 4 samples spanning y/z in [-0.01290704204, 0.03467658074] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 34.31254931, 3152.345098>
  right <0, 150, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 4788.9207
  pigment { function { max(0.002, min(0.98, 0.619612 * (1 + -0.14107 * ((y / 4788.9207) - 0.01088476935) / 0.02379181139 + 0 * sin(19.822795 * ((y / 4788.9207) - 0.01088476935) / 0.02379181139 + 2.75817)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 12.03548609, 1251.951012> + 37558.5 * <0.8055246426, 0.1104847652, -0.5821710803> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, 12.03548609, 1251.951012>;  // mm
#declare V_0 = <212.689709, 245.564946, 161.1310044>;  // mm/s
#declare TC_0 = 0.0892380898303195;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.137141188, 0.04655199389, 0.05772355446> }
  finish { ambient 0.1588 diffuse 0.8412 } }
  no_shadow
  rotate <14.38937865, 245.4235636, 79.01049284>
  transform { Axis_Rotate_Trans(<0.0877527505, -0.9117342117, 0.4012981212>, 66.61088 * (T - TC_0)) }
  scale 11.42838498
  translate P_0 }
#end
