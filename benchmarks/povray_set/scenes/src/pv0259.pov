// validation scene pv0259 (seed 259)
#version 3.7;
#declare NS = 3;
#declare NLT = 59;
#declare LINES = array[59] { 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73 };
#declare LR = 1008.3710976274334;  // line rate, Hz
#declare TAU = 0.0005688250528409727;  // exposure, s
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
// film: 548 x 4 samples spanning y/z in [-0.05378972654, 0.05468227827] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 0.5632308316, 1262.068771>
  right <0, 136.8991298, 0>
  up <1, 0, 0>
  aperture 9.9651954 blur_samples 19 focal_point <0, 0.451552167, 1011.823> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 7219.4796
  pigment { function { max(0.002, min(0.98, 0.0496973 * (1 + -0.178134 * ((y / 7219.4796) - 0.0004462758642) / 0.0542360024 + 0 * sin(21.131851 * ((y / 7219.4796) - 0.0004462758642) / 0.0542360024 + 1.0315)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 20.04945476, 1620.016809> + 48600.5 * <-0.483734878, -0.867589007, 0.1152817534> color rgb FL }
light_source { <0, 20.04945476, 1620.016809> + 48600.5 * <0.04045549165, -0.994921604, -0.09216482616> color rgb FL * 0.2542 }


// ball 0: plain
#declare C0_0 = <0, 20.04945476, 1620.016809>;  // mm
#declare V_0 = <1016.970388, 1099.570026, 54.3898224>;  // mm/s
#declare TC_0 = 0.043634729420077886;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.6337645707, 0.3386309006, 0.6246106237> }
  finish { ambient 0.2484 diffuse 0.7516 } }
  no_shadow
  rotate <207.6667819, 343.0612772, 148.1662952>
  transform { Axis_Rotate_Trans(<0.8306193717, 0.09276137238, 0.5490599122>, 940.90641 * (T - TC_0)) }
  scale 26.79441057
  translate P_0 }
#end
