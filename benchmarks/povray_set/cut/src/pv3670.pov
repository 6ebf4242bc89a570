// validation scene pv3670 (seed 3670)
#version 3.7;
#declare NS = 1;
#declare NLT = 46;
#declare LINES = array[46] { 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72 };
#declare LR = 827.645085888586;  // line rate, Hz
#declare TAU = 9.038482083680739e-05;  // exposure, s
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
// film: 1072 x 4 samples spanning y/z in [0.1916631082, 0.251582042] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 240.3075259, 1084.309781>
  right <0, 64.97068606, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 6490.6571
  pigment { function { max(0.002, min(0.98, 0.595313 * (1 + -0.38659 * ((y / 6490.6571) - 0.2216225751) / 0.02995946693 + 0 * sin(14.503801 * ((y / 6490.6571) - 0.2216225751) / 0.02995946693 + 3.8002)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 597.9356548, 2765.762123> + 82972.9 * <-0.3400900336, -0.1362982803, -0.9304630825> color rgb FL }


// ball 0: golf
#declare C0_0 = <0, 597.9356548, 2765.762123>;  // mm
#declare V_0 = <395.2048067, 41.14045144, 159.0773174>;  // mm/s
#declare TC_0 = 0.09182680027442439;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.1568588047, 0.1568588047, 0.1568588047> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.493 diffuse 0.507 phong 0.35 phong_size 40 } }
  no_shadow
  rotate <208.2844438, 317.7895409, 265.1252781>
  transform { Axis_Rotate_Trans(<0.1340359362, 0.9654214797, 0.2235972593>, 99.596715 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
