// validation scene pv0021 (seed 21)
#version 3.7;
#declare NS = 1;
#declare NLT = 79;
#declare LINES = array[79] { 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99 };
#declare LR = 3172.3011606479454;  // line rate, Hz
#declare TAU = 1.6183703731499063e-05;  // exposure, s
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
// film: 1968 x 4 samples spanning y/z in [-0.0530772969, 0.04953602416] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -2.122417161, 1198.67478>
  right <0, 123, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 6023.4235
  pigment { function { max(0.002, min(0.98, 0.711323 * (1 + -0.276072 * ((y / 6023.4235) - -0.00177063637) / 0.05130666053 + 0.205782 * sin(17.408102 * ((y / 6023.4235) - -0.00177063637) / 0.05130666053 + 6.27868)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -93.35850062, 1887.829947> + 56634.9 * <-0.04177227463, 0.1193726553, -0.9919703858> color rgb FL }


// ball 0: golf
#declare C0_0 = <0, -93.35850062, 1887.829947>;  // mm
#declare V_0 = <1877.967667, 351.7639877, 157.6971063>;  // mm/s
#declare TC_0 = 0.01891371498529003;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.09421551692, 0.09421551692, 0.09421551692> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.4939 diffuse 0.5061 phong 0.4753 phong_size 40 } }
  no_shadow
  rotate <224.4827103, 66.77383353, 46.74740612>
  transform { Axis_Rotate_Trans(<0.1826340179, 0.2441422698, 0.9523861442>, 1377.3767 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
