// validation scene pv4147 (seed 4147)
#version 3.7;
#declare NS = 1;
#declare NLT = 95;
#declare LINES = array[95] { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94 };
#declare LR = 212036.33526843903;  // line rate, Hz
#declare TAU = 7.065904482298206e-07;  // exposure, s
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
// film: 2640 x 4 samples spanning y/z in [-0.08188614697, 0.09593002773] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 6.516690166, 928.0469232>
  right <0, 165.0217538, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 1863.7788
  pigment { function { max(0.002, min(0.98, 0.700841 * (1 + -0.206994 * ((y / 1863.7788) - 0.007021940382) / 0.08890808735 + 0.222087 * sin(11.00905 * ((y / 1863.7788) - 0.007021940382) / 0.08890808735 + 1.97579)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -37.45963798, 792.8143579> + 23784.4 * <-0.1686037698, -0.1690663296, -0.9710763848> color rgb FL }
light_source { <0, -37.45963798, 792.8143579> + 23784.4 * <-0.6641528263, 0.7439200554, -0.07405386163> color rgb FL * 0.6458 }


// ball 0: golf
#declare C0_0 = <0, -37.45963798, 792.8143579>;  // mm
#declare V_0 = <-56804.06506, 5599.432493, 22800.00741>;  // mm/s
#declare TC_0 = 5.187790095539025e-05;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.2779577247, 0.2779577247, 0.2779577247> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.4768 diffuse 0.5232 phong 0.35 phong_size 40 } }
  no_shadow
  rotate <198.8501626, 1.259058091, 5.546644116>
  transform { Axis_Rotate_Trans(<-0.5409112938, -0.6835287911, -0.4901054621>, 1251.5652 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
