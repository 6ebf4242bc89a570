// validation scene pv4030 (seed 4030)
#version 3.7;
#declare NS = 1;
#declare NLT = 73;
#declare LINES = array[73] { 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102 };
#declare LR = 773.0345985935791;  // line rate, Hz
#declare TAU = 0.000860708385234319;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.174136 * sin(753.9822369 * T + 0.730092));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 2096 x 4 samples spanning y/z in [-0.2598155883, -0.2256442213] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -904.6890519, 3727.142943>
  right <0, 127.3615697, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 16846.879
  pigment { function { max(0.002, min(0.98, 0.166964 * (1 + -0.304667 * ((y / 16846.879) - -0.2427299048) / 0.01708568354 + 0.230207 * sin(8.6441361 * ((y / 16846.879) - -0.2427299048) / 0.01708568354 + 4.84725)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -1355.874421, 5406.71258> + 162201 * <0.2610679576, 0.3038025666, -0.9162682588> color rgb FL }
light_source { <0, -1355.874421, 5406.71258> + 162201 * <-0.5644726303, -0.659815228, -0.4959985025> color rgb FL * 0.4671 }


// ball 0: golf
#declare C0_0 = <0, -1355.874421, 5406.71258>;  // mm
#declare V_0 = <-329.7261155, 24.8909521, -175.9233165>;  // mm/s
#declare TC_0 = 0.10866266549107303;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.6869517717, 0.6869517717, 0.6869517717> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.5275 diffuse 0.4725 phong 0.35 phong_size 40 } }
  no_shadow
  rotate <11.05353616, 301.00743, 81.39894038>
  transform { Axis_Rotate_Trans(<-0.8507939454, -0.5250258727, 0.02230460565>, 0 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
