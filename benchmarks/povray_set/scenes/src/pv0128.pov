// validation scene pv0128 (seed 128)
#version 3.7;
#declare NS = 2;
#declare NLT = 67;
#declare LINES = array[67] { 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85 };
#declare LR = 590.9778280534345;  // line rate, Hz
#declare TAU = 0.0004890689144982106;  // exposure, s
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
// film: 1424 x 4 samples spanning y/z in [0.221139017, 0.2376601605] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 1205.506153, 5255.049321>
  right <0, 86.81942403, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 8608.2984
  pigment { function { max(0.002, min(0.98, 0.0266503 * (1 + 0.0654628 * ((y / 8608.2984) - 0.2293995887) / 0.008260571759 + 0.0137935 * sin(22.809846 * ((y / 8608.2984) - 0.2293995887) / 0.008260571759 + 6.06485)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 888.9049117, 3864.031255> + 115921 * <0.2457575116, 0.2442572419, -0.9380520483> color rgb FL }


// ball 0: pingpong
#declare C0_0 = <0, 888.9049117, 3864.031255>;  // mm
#declare V_0 = <379.3094867, -65.48638088, -7.570439489>;  // mm/s
#declare TC_0 = 0.08798976464358713;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.9404846184, 0.9404846184, 0.9404846184> }
  finish { ambient 0.3663 diffuse 0.6337 phong 0.3 phong_size 40 } }
  no_shadow
  rotate <124.4872253, 142.7827927, 60.73117107>
  transform { Axis_Rotate_Trans(<0.810829563, -0.2740651931, -0.5171495815>, 2.0988018 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
