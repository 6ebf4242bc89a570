// validation scene pv0047 (seed 47)
#version 3.7;
#declare NS = 1;
#declare NLT = 39;
#declare LINES = array[39] { 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48 };
#declare LR = 111.44139881862424;  // line rate, Hz
#declare TAU = 0.00048548233526710534;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.0689746 * sin(628.3185307 * T + 2.87294));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 3200 x 4 samples spanning y/z in [0.07587063056, 0.2294921668] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 198.7760341, 1301.900794>
  right <0, 200, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 4320.4649
  pigment { function { max(0.002, min(0.98, 0.141753 * (1 + -0.317858 * ((y / 4320.4649) - 0.1526813987) / 0.07681076814 + 0.163805 * sin(6.1335026 * ((y / 4320.4649) - 0.1526813987) / 0.07681076814 + 5.52416)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 144.9928924, 1166.048239> + 34981.4 * <-0.07073598632, -0.1316664592, -0.9887670928> color rgb FL }


// ball 0: golf
#declare C0_0 = <0, 144.9928924, 1166.048239>;  // mm
#declare V_0 = <-138.6241102, -165.7582023, -7.561678747>;  // mm/s
#declare TC_0 = 0.26022645361082347;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.921985361, 0.921985361, 0.921985361> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.3311 diffuse 0.6689 phong 0.35 phong_size 40 } }
  no_shadow
  rotate <218.5316787, 113.3594125, 116.4611383>
  transform { Axis_Rotate_Trans(<-0.3852463959, 0.8650751155, -0.3212946609>, 0 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
