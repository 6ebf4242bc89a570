// validation scene pv5882 (seed 5882)
#version 3.7;
#declare NS = 1;
#declare NLT = 75;
#declare LINES = array[75] { 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94 };
#declare LR = 19276.68639808822;  // line rate, Hz
#declare TAU = 1.5330998989704785e-05;  // exposure, s
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
// film: 2736 x 4 samples spanning y/z in [-0.04737591388, 0.05263072784] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 4.492567549, 1709.886434>
  right <0, 171, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 4749.2456
  pigment { function { max(0.002, min(0.98, 0.0596193 * (1 + -0.0792887 * ((y / 4749.2456) - 0.002627406978) / 0.05000332086 + 0.0979801 * sin(4.2979884 * ((y / 4749.2456) - 0.002627406978) / 0.05000332086 + 0.482697)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 64.92641563, 1334.590458> + 40037.7 * <0.6505884141, -0.7101643283, 0.2690749749> color rgb FL }


// ball 0: golf
#declare C0_0 = <0, 64.92641563, 1334.590458>;  // mm
#declare V_0 = <-11857.55196, -711.8628737, -336.2347282>;  // mm/s
#declare TC_0 = 0.0029569397365749035;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.7509217465, 0.7509217465, 0.7509217465> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.5892 diffuse 0.4108 phong 0.4262 phong_size 40 } }
  no_shadow
  rotate <33.20016051, 139.3086281, 183.7166664>
  transform { Axis_Rotate_Trans(<-0.4808560795, 0.5437522163, -0.6878306173>, 0 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
