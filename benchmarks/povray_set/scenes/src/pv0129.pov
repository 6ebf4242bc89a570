// validation scene pv0129 (seed 129)
#version 3.7;
#declare NS = 1;
#declare NLT = 59;
#declare LINES = array[59] { 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73 };
#declare LR = 161.39809030263115;  // line rate, Hz
#declare TAU = 0.00022936888004688156;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.10158 * sin(753.9822369 * T + 3.97129));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 1664 x 4 samples spanning y/z in [-0.01280407659, 0.01057751515] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -4.952010344, 4448.123684>
  right <0, 104.004212, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 14716.631
  pigment { function { max(0.002, min(0.98, 0.710595 * (1 + -0.268096 * ((y / 14716.631) - -0.001113280722) / 0.01169079587 + 0.155146 * sin(13.480913 * ((y / 14716.631) - -0.001113280722) / 0.01169079587 + 5.25375)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -1.444475421, 3239.137945> + 97174.1 * <-0.2300465714, 0.5996812945, -0.7664599924> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, -1.444475421, 3239.137945>;  // mm
#declare V_0 = <88.24591789, 56.78292193, 6.503456811>;  // mm/s
#declare TC_0 = 0.27261784769260494;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.1451027349, 0.177467237, 0.1958673993> }
  finish { ambient 0.4442 diffuse 0.5558 } }
  no_shadow
  rotate <255.2189534, 255.0400527, 94.36691695>
  transform { Axis_Rotate_Trans(<0.3542169842, -0.8795501745, -0.3176819456>, 44.317955 * (T - TC_0)) }
  scale 14.51180363
  translate P_0 }
#end
