// validation scene pv0202 (seed 202)
#version 3.7;
#declare NS = 1;
#declare NLT = 31;
#declare LINES = array[31] { 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36 };
#declare LR = 16549.919019781777;  // line rate, Hz
#declare TAU = 4.405115050932388e-06;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.23879 * sin(628.3185307 * T + 3.2071));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 1920 x 4 samples spanning y/z in [-0.01242122419, 0.01082627735] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -4.116434205, 5161.845018>
  right <0, 120, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 9180.6718
  pigment { function { max(0.002, min(0.98, 0.772405 * (1 + 0.296193 * ((y / 9180.6718) - -0.0007974734209) / 0.01162375077 + 0.112511 * sin(7.1990942 * ((y / 9180.6718) - -0.0007974734209) / 0.01162375077 + 3.1048)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 19.7232818, 2197.419501> + 65922.6 * <-0.5597649639, 0.09710754508, -0.822941863> color rgb FL }
light_source { <0, 19.7232818, 2197.419501> + 65922.6 * <-0.8263536313, -0.5617548687, -0.0396376527> color rgb FL * 0.699 }


// ball 0: plain
#declare C0_0 = <0, 19.7232818, 2197.419501>;  // mm
#declare V_0 = <13720.94517, -1786.504067, -1354.676872>;  // mm/s
#declare TC_0 = 0.0012688883839793495;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.05812810967, 0.07843340145, 0.1616285065> }
  finish { ambient 0.2154 diffuse 0.7846 } }
  no_shadow
  rotate <296.3310906, 76.45677606, 247.6467432>
  transform { Axis_Rotate_Trans(<-0.6575757308, -0.2293471823, -0.7176308439>, 10086.693 * (T - TC_0)) }
  scale 10.6066777
  translate P_0 }
#end
