// validation scene pu2013 (seed 2013)
#version 3.7;
#declare NS = 1;
#declare NLT = 41;
#declare LINES = array[41] { 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50 };
#declare LR = 3956.467144643363;  // line rate, Hz
#declare TAU = 0.00015951889354119697;  // exposure, s
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
// film: 2368 x 4 samples spanning y/z in [-0.0776203199, 0.07649386713] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -0.5405545587, 959.7465072>
  right <0, 147.9105527, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 14556.636
  pigment { function { max(0.002, min(0.98, 0.212032 * (1 + -0.302664 * ((y / 14556.636) - -0.0005632263881) / 0.07705709351 + 0.101736 * sin(14.161709 * ((y / 14556.636) - -0.0005632263881) / 0.07705709351 + 5.46777)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -71.73363276, 3805.869888> + 114176 * <0.4469524423, 0.6356006759, -0.6294801785> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, -71.73363276, 3805.869888>;  // mm
#declare V_0 = <-5060.613515, -350.3620789, -1104.408028>;  // mm/s
#declare TC_0 = 0.007582522210658774;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.703544418, 0.703544418, 0.703544418> }
  finish { ambient 1 diffuse 0 } }
  no_shadow
  rotate <130.5251807, 155.3671543, 232.2462671>
  transform { Axis_Rotate_Trans(<0.2323590337, -0.8310498721, 0.5053369069>, 641.58432 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
