// validation scene pv0038 (seed 38)
#version 3.7;
#declare NS = 1;
#declare NLT = 29;
#declare LINES = array[29] { 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35 };
#declare LR = 84.11053454390193;  // line rate, Hz
#declare TAU = 0.001189925833736732;  // exposure, s
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
// film: 1584 x 4 samples spanning y/z in [-0.08791003851, 0.02444275071] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -27.96219629, 881.1530242>
  right <0, 99, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 19469.668
  pigment { function { max(0.002, min(0.98, 0.486112 * (1 + 0.221969 * ((y / 19469.668) - -0.0317336439) / 0.05617639461 + 0.197546 * sin(16.762896 * ((y / 19469.668) - -0.0317336439) / 0.05617639461 + 4.04265)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -397.7004946, 4662.375514> + 139871 * <0.2847495972, 0.5853257544, -0.759151782> color rgb FL }
light_source { <0, -397.7004946, 4662.375514> + 139871 * <0.8758021652, 0.4814714686, -0.0339969456> color rgb FL * 0.5468 }


// ball 0: golf
#declare C0_0 = <0, -397.7004946, 4662.375514>;  // mm
#declare V_0 = <-158.1742686, -116.4715146, 111.6929172>;  // mm/s
#declare TC_0 = 0.24967146046419358;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.1561547092, 0.1561547092, 0.1561547092> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.4334 diffuse 0.5666 phong 0.35 phong_size 40 } }
  no_shadow
  rotate <334.6409328, 141.863201, 127.5943849>
  transform { Axis_Rotate_Trans(<0.4741194154, -0.8675450766, 0.1502541849>, 0 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
