// validation scene pv0195 (seed 195)
#version 3.7;
#declare NS = 1;
#declare NLT = 35;
#declare LINES = array[35] { 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43 };
#declare LR = 1916.5049706354089;  // line rate, Hz
#declare TAU = 3.848487721873402e-05;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.0942144 * sin(753.9822369 * T + 3.98811));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 3056 x 4 samples spanning y/z in [-0.02779193489, 0.03832746139] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 15.21320381, 2887.981689>
  right <0, 190.9516057, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 16325.885
  pigment { function { max(0.002, min(0.98, 0.530844 * (1 + 0.320041 * ((y / 16325.885) - 0.005267763252) / 0.03305969814 + 0.216318 * sin(14.613043 * ((y / 16325.885) - 0.005267763252) / 0.03305969814 + 0.464247)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 80.51683495, 6923.977828> + 207719 * <0.54480573, 0.1817276609, -0.8186340903> color rgb FL }


// ball 0: pingpong
#declare C0_0 = <0, 80.51683495, 6923.977828>;  // mm
#declare V_0 = <2593.653694, 70.96727031, 426.6306077>;  // mm/s
#declare TC_0 = 0.013566361892283437;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.1944341096, 0.08749534933, 0.009721705481> }
  finish { ambient 0.5346 diffuse 0.4654 phong 0.3 phong_size 40 } }
  no_shadow
  rotate <144.0215893, 74.90213169, 97.12560038>
  transform { Axis_Rotate_Trans(<-0.0907440807, 0.04153038498, 0.995007909>, 0 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
