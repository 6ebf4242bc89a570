// validation scene pv0169 (seed 169)
#version 3.7;
#declare NS = 1;
#declare NLT = 29;
#declare LINES = array[29] { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28 };
#declare LR = 1736.2059243135004;  // line rate, Hz
#declare TAU = 4.4805394925267106e-05;  // exposure, s
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
// film: 1248 x 4 samples spanning y/z in [-0.0190603709, 0.02822961804] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 7.561581259, 1649.33525>
  right <0, 77.99704571, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 16999.639
  pigment { function { max(0.002, min(0.98, 0.571616 * (1 + -0.332795 * ((y / 16999.639) - 0.004584623569) / 0.02364499447 + 0.167356 * sin(23.682371 * ((y / 16999.639) - 0.004584623569) / 0.02364499447 + 3.40656)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 2.095449722, 6080.664983> + 182420 * <0.7485893934, -0.1483067503, -0.6462344992> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, 2.095449722, 6080.664983>;  // mm
#declare V_0 = <-3323.965092, 1888.018262, -756.6297442>;  // mm/s
#declare TC_0 = 0.005183716904755189;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.05771875482, 0.127200229, 0.07080047882> }
  finish { ambient 0.175 diffuse 0.825 } }
  no_shadow
  rotate <326.9077594, 16.01838038, 112.352254>
  transform { Axis_Rotate_Trans(<0.1385960414, -0.9706807277, 0.1963926223>, 50.560313 * (T - TC_0)) }
  scale 31.51130904
  translate P_0 }
#end
