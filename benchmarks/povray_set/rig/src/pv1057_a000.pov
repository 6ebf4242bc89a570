// validation scene pv1057_a000 (seed 1057)
#version 3.7;
#declare NS = 1;
#declare NLT = 85;
#declare LINES = array[85] { 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108 };
#declare LR = 57417.13561033153;  // line rate, Hz
#declare TAU = 6.837085825407106e-07;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.146597 * sin(628.3185307 * T + 0.656914));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 1792 x 4 samples spanning y/z in [-0.06191943747, 0.04639397679] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -8.026944809, 1034.03628>
  right <0, 112, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 5523.6381
  pigment { function { max(0.002, min(0.98, 0.0481642 * (1 + -0.0175609 * ((y / 5523.6381) - -0.007762730342) / 0.05415670713 + 0 * sin(11.520818 * ((y / 5523.6381) - -0.007762730342) / 0.05415670713 + 1.91149)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 22.15975065, 1330.670329> + 39920.1 * <-0.6044069179, 0.5544693785, -0.5720629213> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, 22.15975065, 1330.670329>;  // mm
#declare V_0 = <-26153.02597, 2200.655254, 2489.040692>;  // mm/s
#declare TC_0 = 0.0011494826291565143;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.8867186321, 0.1902623773, 0.7863495059> }
  finish { ambient 0.3363 diffuse 0.6637 } }
  no_shadow
  rotate <74.50188019, 88.94034818, 211.1324475>
  transform { Axis_Rotate_Trans(<0.5313874439, -0.8177608786, 0.2211210753>, 0 * (T - TC_0)) }
  scale 17.90727453
  translate P_0 }
#end
