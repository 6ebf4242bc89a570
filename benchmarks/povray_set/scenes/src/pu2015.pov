// validation scene pu2015 (seed 2015)
#version 3.7;
#declare NS = 1;
#declare NLT = 53;
#declare LINES = array[53] { 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66 };
#declare LR = 1884.2191087894714;  // line rate, Hz
#declare TAU = 0.00013474812185124667;  // exposure, s
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
// film: 344 x 4 samples spanning y/z in [-0.04554046072, 0.0545896698] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 3.886102898, 858.882332>
  right <0, 86, 0>
  up <1, 0, 0>
  aperture 84.681937 blur_samples 19 focal_point <0, 20.91784916, 4623.1331> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 37692.02
  pigment { function { max(0.002, min(0.98, 0.0244144 * (1 + 0.193167 * ((y / 37692.02) - 0.004524604539) / 0.05006506526 + 0.240008 * sin(5.7060004 * ((y / 37692.02) - 0.004524604539) / 0.05006506526 + 2.55657)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 73.30809982, 7677.486035> + 230325 * <-0.2972645074, 0.7357585378, -0.6085172032> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, 73.30809982, 7677.486035>;  // mm
#declare V_0 = <8890.85491, 110.9734618, 86.21633431>;  // mm/s
#declare TC_0 = 0.02122895358263204;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.9131524981, 0.9131524981, 0.9131524981> }
  finish { ambient 1 diffuse 0 } }
  no_shadow
  rotate <112.8819026, 198.8601471, 289.817291>
  transform { Axis_Rotate_Trans(<-0.1089967877, 0.8593627606, 0.499615198>, 2588.5465 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
