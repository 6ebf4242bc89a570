// validation scene pu2033 (seed 2033)
#version 3.7;
#declare NS = 2;
#declare NLT = 35;
#declare LINES = array[35] { 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42 };
#declare LR = 1801.9519355250548;  // line rate, Hz
#declare TAU = 0.0001868525503342215;  // exposure, s
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
// film: 1664 x 4 samples spanning y/z in [0.1086895785, 0.1882278226] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 194.1167427, 1307.547095>
  right <0, 104, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 14057.923
  pigment { function { max(0.002, min(0.98, 0.049229 * (1 + -0.1014 * ((y / 14057.923) - 0.1484587006) / 0.03976912204 + 0.0147333 * sin(12.384177 * ((y / 14057.923) - 0.1484587006) / 0.03976912204 + 5.08387)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 438.1192861, 2862.666043> + 85880 * <-0.6973352742, 0.2838931367, -0.6581247619> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, 438.1192861, 2862.666043>;  // mm
#declare V_0 = <-4195.814499, -64.581916, 601.1784842>;  // mm/s
#declare TC_0 = 0.013873843972822434;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.491183025, 0.5964365304, 0.1052535054> }
  finish { ambient 1 diffuse 0 } }
  no_shadow
  rotate <349.6962227, 213.5106307, 278.0190812>
  transform { Axis_Rotate_Trans(<-0.2069684118, 0.2474802476, -0.9465292407>, 3577.1212 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
