// validation scene pu2011 (seed 2011)
#version 3.7;
#declare NS = 1;
#declare NLT = 71;
#declare LINES = array[71] { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70 };
#declare LR = 66188.10645300511;  // line rate, Hz
#declare TAU = 1.162367365445106e-05;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.106825 * sin(628.3185307 * T + 0.896521));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 1168 x 4 samples spanning y/z in [-0.04045765327, 0.03630941724] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -1.972338063, 950.9285624>
  right <0, 73, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 14633.88
  pigment { function { max(0.002, min(0.98, 0.0227482 * (1 + 0.193593 * ((y / 14633.88) - -0.002074118016) / 0.03838353525 + 0 * sin(5.5313702 * ((y / 14633.88) - -0.002074118016) / 0.03838353525 + 1.77445)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -42.06346031, 4014.358294> + 120431 * <0.04407144109, 0.08654332217, -0.9952728076> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, -42.06346031, 4014.358294>;  // mm
#declare V_0 = <-25576.93808, 16245.32552, -2482.38475>;  // mm/s
#declare TC_0 = 0.00010575918205138776;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.8947562465, 0.8947562465, 0.8947562465> }
  finish { ambient 1 diffuse 0 } }
  no_shadow
  rotate <294.4904139, 276.1384591, 299.57727>
  transform { Axis_Rotate_Trans(<-0.3262910797, 0.08980060353, -0.9409941461>, 14330.15 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
