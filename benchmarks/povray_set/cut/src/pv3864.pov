// validation scene pv3864 (seed 3864)
#version 3.7;
#declare NS = 1;
#declare NLT = 73;
#declare LINES = array[73] { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72 };
#declare LR = 27127.770159292086;  // line rate, Hz
#declare TAU = 2.0027754544950165e-05;  // exposure, s
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
// film: 3152 x 4 samples spanning y/z in [-0.06652203724, 0.0545070875] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -9.784309041, 1628.689134>
  right <0, 197.1188203, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 7065.4853
  pigment { function { max(0.002, min(0.98, 0.0140294 * (1 + 0.231146 * ((y / 7065.4853) - -0.00600747487) / 0.06051456237 + 0 * sin(14.697746 * ((y / 7065.4853) - -0.00600747487) / 0.06051456237 + 5.13681)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -45.03323536, 1710.727675> + 51321.8 * <-0.2059153625, -0.04022394261, -0.9777427565> color rgb FL }


// ball 0: golf
#declare C0_0 = <0, -45.03323536, 1710.727675>;  // mm
#declare V_0 = <-9319.2122, -1175.048635, 216.9140049>;  // mm/s
#declare TC_0 = 0.00025803816380397514;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.6735136796, 0.6735136796, 0.6735136796> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.1158 diffuse 0.8842 phong 0.2286 phong_size 40 } }
  no_shadow
  rotate <337.8117926, 161.0749097, 177.6849673>
  transform { Axis_Rotate_Trans(<0.6559815332, -0.7292489658, 0.1946385728>, 5869.3105 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
