// validation scene pv0026 (seed 26)
#version 3.7;
#declare NS = 1;
#declare NLT = 33;
#declare LINES = array[33] { 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40 };
#declare LR = 252.9138697251632;  // line rate, Hz
#declare TAU = 0.00022816401790908022;  // exposure, s
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
// film: 1840 x 4 samples spanning y/z in [-0.03122997157, 0.03698807671] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 4.853423018, 1685.770891>
  right <0, 115, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 18795.98
  pigment { function { max(0.002, min(0.98, 0.024116 * (1 + -0.280048 * ((y / 18795.98) - 0.002879052572) / 0.03410902414 + 0.0496566 * sin(13.396126 * ((y / 18795.98) - 0.002879052572) / 0.03410902414 + 0.437452)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 21.35041695, 5177.058199> + 155312 * <0.5912961824, 0.5508653291, -0.5889959371> color rgb FL }
light_source { <0, 21.35041695, 5177.058199> + 155312 * <-0.9840604164, -0.008395358955, -0.1776361869> color rgb FL * 0.5934 }


// ball 0: plain
#declare C0_0 = <0, 21.35041695, 5177.058199>;  // mm
#declare V_0 = <2075.659779, -48.83040554, -75.77948326>;  // mm/s
#declare TC_0 = 0.09489396538861374;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.4935260502, 0.7076963201, 0.9852708457> }
  finish { ambient 0.4118 diffuse 0.5882 } }
  no_shadow
  rotate <138.8134267, 152.325705, 54.64292008>
  transform { Axis_Rotate_Trans(<0.6960121896, 0.6852803188, 0.214377976>, 0 * (T - TC_0)) }
  scale 118.7426759
  translate P_0 }
#end
