// validation scene pv0232 (seed 232)
#version 3.7;
#declare NS = 1;
#declare NLT = 33;
#declare LINES = array[33] { 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40 };
#declare LR = 446.4047513743025;  // line rate, Hz
#declare TAU = 9.67178220354391e-05;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.222734 * sin(753.9822369 * T + 2.32903));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 1344 x 4 samples spanning y/z in [-0.1437097182, -0.1033078697] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -259.8752118, 2104.102902>
  right <0, 85.00964657, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 11967.023
  pigment { function { max(0.002, min(0.98, 0.65209 * (1 + -0.296424 * ((y / 11967.023) - -0.123508794) / 0.02020092423 + 0.115635 * sin(9.3584999 * ((y / 11967.023) - -0.123508794) / 0.02020092423 + 2.424)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -600.6405119, 4720.534971> + 141616 * <-0.234414645, -0.7666144877, -0.5977892617> color rgb FL }


// ball 0: pingpong
#declare C0_0 = <0, -600.6405119, 4720.534971>;  // mm
#declare V_0 = <-646.9701427, -209.0548474, -280.9617924>;  // mm/s
#declare TC_0 = 0.05376286862116399;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.1257174457, 0.1257174457, 0.1257174457> }
  finish { ambient 0.1539 diffuse 0.8461 phong 0.7839 phong_size 40 } }
  no_shadow
  rotate <270.6216068, 201.9142343, 316.5847677>
  transform { Axis_Rotate_Trans(<0.7447421429, 0.473500431, -0.4702727744>, 472.28136 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
