// validation scene pv0150 (seed 150)
#version 3.7;
#declare NS = 5;
#declare NLT = 47;
#declare LINES = array[47] { 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57 };
#declare LR = 36349.447739183655;  // line rate, Hz
#declare TAU = 1.9031534723765708e-05;  // exposure, s
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
// film: 548 x 4 samples spanning y/z in [-0.1179814676, -0.04436104699] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -150.637372, 1855.796954>
  right <0, 136.6245523, 0>
  up <1, 0, 0>
  aperture 6.6301305 blur_samples 19 focal_point <0, -67.63337981, 833.21833> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 3089.4677
  pigment { function { max(0.002, min(0.98, 0.0351941 * (1 + 0.339929 * ((y / 3089.4677) - -0.0811712573) / 0.03681021032 + 0 * sin(7.6953727 * ((y / 3089.4677) - -0.0811712573) / 0.03681021032 + 2.76806)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -115.5224878, 1378.669553> + 41360.1 * <0.4639910768, -0.2401434244, -0.8526684094> color rgb FL }


// ball 0: golf
#declare C0_0 = <0, -115.5224878, 1378.669553>;  // mm
#declare V_0 = <37804.27558, -18210.17551, -8525.19976>;  // mm/s
#declare TC_0 = 0.0009353649674118427;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.7220276152, 0.7220276152, 0.7220276152> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.4365 diffuse 0.5635 phong 0.6684 phong_size 40 } }
  no_shadow
  rotate <91.34931044, 343.1174299, 211.6348802>
  transform { Axis_Rotate_Trans(<0.4006428769, 0.6360672572, -0.6594723114>, 8988.3821 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
