// validation scene pv0286 (seed 286)
#version 3.7;
#declare NS = 2;
#declare NLT = 30;
#declare LINES = array[30] { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29 };
#declare LR = 4824.613929485154;  // line rate, Hz
#declare TAU = 7.226747984551708e-05;  // exposure, s
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
// film: 1152 x 4 samples spanning y/z in [-0.008261325255, 0.01230640314] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 7.080159801, 3500.629658>
  right <0, 72, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 9451.4196
  pigment { function { max(0.002, min(0.98, 0.212439 * (1 + 0.0266191 * ((y / 9451.4196) - 0.002022538941) / 0.0102838642 + 0 * sin(7.2583331 * ((y / 9451.4196) - 0.002022538941) / 0.0102838642 + 3.95679)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -2.630426096, 3166.602647> + 94998.1 * <0.5938194638, 0.6139829039, -0.5200033058> color rgb FL }
light_source { <0, -2.630426096, 3166.602647> + 94998.1 * <-0.9569051995, 0.2902016347, -0.01074478198> color rgb FL * 0.4792 }


// ball 0: plain
#declare C0_0 = <0, -2.630426096, 3166.602647>;  // mm
#declare V_0 = <5149.7023, 35.08445913, -1476.240719>;  // mm/s
#declare TC_0 = 0.002072704706771662;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.790501261, 0.4752836128, 0.7433806425> }
  finish { ambient 0.3834 diffuse 0.6166 } }
  no_shadow
  rotate <220.7411975, 162.0377739, 143.3399501>
  transform { Axis_Rotate_Trans(<-0.5856108161, -0.5875997972, 0.5583784114>, 1901.889 * (T - TC_0)) }
  scale 17.59969034
  translate P_0 }
#end
