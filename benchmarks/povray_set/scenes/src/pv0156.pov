// validation scene pv0156 (seed 156)
#version 3.7;
#declare NS = 1;
#declare NLT = 81;
#declare LINES = array[81] { 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109 };
#declare LR = 28705.040298604654;  // line rate, Hz
#declare TAU = 1.5799020043003951e-06;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.278601 * sin(753.9822369 * T + 5.94049));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 1504 x 4 samples spanning y/z in [-0.004833794619, 0.00475471863] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -0.3876066467, 9803.39679>
  right <0, 94, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 53968.076
  pigment { function { max(0.002, min(0.98, 0.29536 * (1 + 0.374045 * ((y / 53968.076) - -3.953799433e-05) / 0.004794256624 + 0 * sin(9.9393859 * ((y / 53968.076) - -3.953799433e-05) / 0.004794256624 + 3.58228)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 28.77131471, 11885.72984> + 356572 * <0.5918541782, -0.2466271621, -0.7673875648> color rgb FL }
light_source { <0, 28.77131471, 11885.72984> + 356572 * <-0.6942978402, 0.4563678462, 0.5564880036> color rgb FL * 0.2932 }


// ball 0: pingpong
#declare C0_0 = <0, 28.77131471, 11885.72984>;  // mm
#declare V_0 = <12136.76185, 637.1342049, 3780.476742>;  // mm/s
#declare TC_0 = 0.0027521299109216084;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.6999862743, 0.6999862743, 0.6999862743> }
  finish { ambient 0.578 diffuse 0.422 phong 0.7577 phong_size 40 } }
  no_shadow
  rotate <25.34886209, 212.7245683, 147.0088376>
  transform { Axis_Rotate_Trans(<-0.9711632959, 0.04360719807, -0.234393398>, 11028.807 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
