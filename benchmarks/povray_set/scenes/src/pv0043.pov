// validation scene pv0043 (seed 43)
#version 3.7;
#declare NS = 1;
#declare NLT = 29;
#declare LINES = array[29] { 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42 };
#declare LR = 53.45334967588817;  // line rate, Hz
#declare TAU = 0.003228765302353577;  // exposure, s
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
// film: 2208 x 4 samples spanning y/z in [-0.005734596764, 0.006227807074] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 2.844876194, 11536.15868>
  right <0, 138.0001888, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 83105.092
  pigment { function { max(0.002, min(0.98, 0.725358 * (1 + 0.166085 * ((y / 83105.092) - 0.0002466051546) / 0.005981201919 + 0.0765579 * sin(23.717908 * ((y / 83105.092) - 0.0002466051546) / 0.005981201919 + 3.85765)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 10.67639473, 13893.22173> + 416797 * <0.3971118916, -0.001506724482, -0.9177689662> color rgb FL }
light_source { <0, 10.67639473, 13893.22173> + 416797 * <-0.9278191642, -0.3709489742, 0.03935043988> color rgb FL * 0.5546 }


// ball 0: golf
#declare C0_0 = <0, 10.67639473, 13893.22173>;  // mm
#declare V_0 = <47.51796158, -28.98569442, -2.905291767>;  // mm/s
#declare TC_0 = 0.7483160595647997;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.1069796978, 0.1069796978, 0.1069796978> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.1728 diffuse 0.8272 phong 0.35 phong_size 40 } }
  no_shadow
  rotate <326.0702298, 205.0776188, 206.9822846>
  transform { Axis_Rotate_Trans(<0.3971849209, -0.9122032547, 0.1006447252>, 0 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
