// validation scene pv0207 (seed 207)
#version 3.7;
#declare NS = 2;
#declare NLT = 33;
#declare LINES = array[33] { 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39 };
#declare LR = 524.5957560183186;  // line rate, Hz
#declare TAU = 0.0017327694921933274;  // exposure, s
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
// film: 1056 x 4 samples spanning y/z in [-0.008305305344, 0.0107761254] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 4.273110492, 3458.860128>
  right <0, 66, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 62553.732
  pigment { function { max(0.002, min(0.98, 0.0180918 * (1 + -0.312601 * ((y / 62553.732) - 0.001235410029) / 0.009540715373 + 0.00189641 * sin(3.603672 * ((y / 62553.732) - 0.001235410029) / 0.009540715373 + 4.1365)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -59.98673722, 13880.57792> + 416417 * <0.3560327596, -0.1419679191, -0.923626431> color rgb FL }
light_source { <0, -59.98673722, 13880.57792> + 416417 * <0.1451386677, -0.5832337119, -0.799232885> color rgb FL * 0.4126 }


// ball 0: pingpong
#declare C0_0 = <0, -59.98673722, 13880.57792>;  // mm
#declare V_0 = <840.298935, -694.6532307, -86.01363769>;  // mm/s
#declare TC_0 = 0.04384328263455652;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.8053980746, 0.8053980746, 0.8053980746> }
  finish { ambient 0.5977 diffuse 0.4023 phong 0.4113 phong_size 40 } }
  no_shadow
  rotate <160.390656, 27.90218149, 314.4090606>
  transform { Axis_Rotate_Trans(<0.2339005877, -0.9722602914, -0.0006639822724>, 548.05572 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
