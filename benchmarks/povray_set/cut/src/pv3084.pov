// validation scene pv3084 (seed 3084)
#version 3.7;
#declare NS = 1;
#declare NLT = 49;
#declare LINES = array[49] { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48 };
#declare LR = 297.5235277177467;  // line rate, Hz
#declare TAU = 0.0002446659242032217;  // exposure, s
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
// film: 1888 x 4 samples spanning y/z in [-0.04883116742, -0.01753559886] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -125.0187562, 3767.510854>
  right <0, 117.9063943, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 10776.135
  pigment { function { max(0.002, min(0.98, 0.0273893 * (1 + 0.340137 * ((y / 10776.135) - -0.03318338314) / 0.01564778428 + 0 * sin(6.1147557 * ((y / 10776.135) - -0.03318338314) / 0.01564778428 + 4.47338)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -109.0877975, 3839.579347> + 115187 * <0.467157942, 0.6399967248, -0.6100554478> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, -109.0877975, 3839.579347>;  // mm
#declare V_0 = <-185.0707063, -10.6832445, 38.81567109>;  // mm/s
#declare TC_0 = 0.006722157455384003;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.2883504604, 0.6317852938, 0.4306524766> }
  finish { ambient 0.2867 diffuse 0.7133 } }
  no_shadow
  rotate <131.575298, 203.7461749, 28.37721251>
  transform { Axis_Rotate_Trans(<-0.4677062146, -0.8444447493, -0.2610822903>, 68.468818 * (T - TC_0)) }
  scale 26.87197324
  translate P_0 }
#end
