// validation scene pu2038 (seed 2038)
#version 3.7;
#declare NS = 1;
#declare NLT = 24;
#declare LINES = array[24] { 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30 };
#declare LR = 654.6264761772034;  // line rate, Hz
#declare TAU = 0.00011825108197703233;  // exposure, s
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
// film: 1744 x 4 samples spanning y/z in [-0.04499369779, 0.04168086658] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -2.083071341, 1257.577708>
  right <0, 109, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 11075.553
  pigment { function { max(0.002, min(0.98, 0.457921 * (1 + 0.304939 * ((y / 11075.553) - -0.001656415606) / 0.04333728219 + 0.222591 * sin(21.531647 * ((y / 11075.553) - -0.001656415606) / 0.04333728219 + 4.32081)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 22.12399647, 2763.674089> + 82910.2 * <0.2741825991, 0.06289895967, -0.959618478> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, 22.12399647, 2763.674089>;  // mm
#declare V_0 = <-1023.039968, 132.6414366, 83.87677461>;  // mm/s
#declare TC_0 = 0.03360695114024801;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.1332866442, 0.1332866442, 0.1332866442> }
  finish { ambient 1 diffuse 0 } }
  no_shadow
  rotate <149.2122842, 15.83702798, 5.845731669>
  transform { Axis_Rotate_Trans(<0.5383609645, -0.6887886379, 0.4855282527>, 101.71842 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
