// validation scene pv0145 (seed 145)
#version 3.7;
#declare NS = 2;
#declare NLT = 37;
#declare LINES = array[37] { 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45 };
#declare LR = 9116.501359760801;  // line rate, Hz
#declare TAU = 3.5704103847796094e-05;  // exposure, s
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
// film: 1296 x 4 samples spanning y/z in [-0.007170561789, 0.005210544303] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -6.411483499, 6542.271733>
  right <0, 81.00056041, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 50591.352
  pigment { function { max(0.002, min(0.98, 0.276763 * (1 + -0.280597 * ((y / 50591.352) - -0.0009800087431) / 0.006190553046 + 0 * sin(19.223184 * ((y / 50591.352) - -0.0009800087431) / 0.006190553046 + 1.99408)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -22.45873862, 8656.270907> + 259688 * <0.6721128348, -0.07841108516, -0.7362852973> color rgb FL }


// ball 0: golf
#declare C0_0 = <0, -22.45873862, 8656.270907>;  // mm
#declare V_0 = <-12017.69822, 904.2977947, -715.6921809>;  // mm/s
#declare TC_0 = 0.002961662477140071;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.6614555067, 0.6614555067, 0.6614555067> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.4217 diffuse 0.5783 phong 0.35 phong_size 40 } }
  no_shadow
  rotate <88.02503604, 334.054865, 150.2933607>
  transform { Axis_Rotate_Trans(<0.9682241606, -0.2463138747, 0.04326025777>, 7737.4495 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
