// validation scene pu2034 (seed 2034)
#version 3.7;
#declare NS = 1;
#declare NLT = 47;
#declare LINES = array[47] { 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57 };
#declare LR = 1465.6842527370113;  // line rate, Hz
#declare TAU = 5.1672995156850144e-05;  // exposure, s
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
// film: 1680 x 4 samples spanning y/z in [-0.05489730489, 0.0607630906] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 2.662568708, 907.8302002>
  right <0, 105, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 1185.2033
  pigment { function { max(0.002, min(0.98, 0.178719 * (1 + 0.100533 * ((y / 1185.2033) - 0.002932892855) / 0.05783019775 + 0.17507 * sin(6.9342782 * ((y / 1185.2033) - 0.002932892855) / 0.05783019775 + 3.66337)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -4.077619556, 492.334871> + 14770 * <-0.5838243433, -0.5724453591, -0.575721675> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, -4.077619556, 492.334871>;  // mm
#declare V_0 = <-838.5691572, -135.3716753, -75.27103758>;  // mm/s
#declare TC_0 = 0.023197356413230594;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.2772964314, 0.7870049304, 0.245949116> }
  finish { ambient 1 diffuse 0 } }
  no_shadow
  rotate <4.107117308, 8.550924152, 68.13284001>
  transform { Axis_Rotate_Trans(<-0.6040941056, -0.4074182477, -0.6848946511>, 0 * (T - TC_0)) }
  scale 11.7352075
  translate P_0 }
#end
