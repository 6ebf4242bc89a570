// validation scene pv3316 (seed 3316)
#version 3.7;
#declare NS = 1;
#declare NLT = 68;
#declare LINES = array[68] { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67 };
#declare LR = 4070.851762256564;  // line rate, Hz
#declare TAU = 1.923354784790292e-05;  // exposure, s
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
// film: 2624 x 4 samples spanning y/z in [-0.0637016249, 0.06409911458] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 0.2550388506, 1283.247661>
  right <0, 164, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 6414.5026
  pigment { function { max(0.002, min(0.98, 0.813063 * (1 + 0.27814 * ((y / 6414.5026) - 0.0001987448396) / 0.06390036974 + 0.0168837 * sin(3.8251299 * ((y / 6414.5026) - 0.0001987448396) / 0.06390036974 + 3.08596)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 24.65487063, 1234.133817> + 37024 * <0.6730402555, 0.2953340899, -0.678081551> color rgb FL }
light_source { <0, 24.65487063, 1234.133817> + 37024 * <0.9719633234, 0.2303622707, 0.04712241647> color rgb FL * 0.4019 }


// ball 0: pingpong
#declare C0_0 = <0, 24.65487063, 1234.133817>;  // mm
#declare V_0 = <-1647.116882, -108.7212391, -2.917979417>;  // mm/s
#declare TC_0 = 0.0036847325513236487;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.2575792632, 0.2575792632, 0.2575792632> }
  finish { ambient 0.4064 diffuse 0.5936 phong 0.6167 phong_size 40 } }
  no_shadow
  rotate <124.8218461, 213.5232436, 36.56646518>
  transform { Axis_Rotate_Trans(<0.2546375284, -0.459166091, 0.851073575>, 0 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
