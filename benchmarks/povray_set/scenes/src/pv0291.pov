// validation scene pv0291 (seed 291)
#version 3.7;
#declare NS = 1;
#declare NLT = 33;
#declare LINES = array[33] { 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40 };
#declare LR = 2389.93772281051;  // line rate, Hz
#declare TAU = 9.928685614442319e-05;  // exposure, s
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
// film: 2208 x 4 samples spanning y/z in [0.1499173986, 0.1910356648] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 572.1486724, 3356.172646>
  right <0, 138, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 25960.645
  pigment { function { max(0.002, min(0.98, 0.0463583 * (1 + -0.156847 * ((y / 25960.645) - 0.1704765317) / 0.02055913306 + 0.137247 * sin(17.22572 * ((y / 25960.645) - 0.1704765317) / 0.02055913306 + 0.28892)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 1144.868699, 6474.878789> + 194246 * <0.5762366762, -0.3383523582, -0.7439549548> color rgb FL }


// ball 0: golf
#declare C0_0 = <0, 1144.868699, 6474.878789>;  // mm
#declare V_0 = <-3658.271799, 1242.424469, 1009.679465>;  // mm/s
#declare TC_0 = 0.010042102675285016;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.6695515787, 0.6695515787, 0.6695515787> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.4222 diffuse 0.5778 phong 0.6815 phong_size 40 } }
  no_shadow
  rotate <42.51095688, 262.8794189, 297.2149984>
  transform { Axis_Rotate_Trans(<-0.3014588232, -0.9534615447, -0.005801789538>, 0 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
