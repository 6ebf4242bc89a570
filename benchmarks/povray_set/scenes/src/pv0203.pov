// validation scene pv0203 (seed 203)
#version 3.7;
#declare NS = 1;
#declare NLT = 129;
#declare LINES = array[129] { 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176 };
#declare LR = 7942.893022851903;  // line rate, Hz
#declare TAU = 5.1947329257520394e-05;  // exposure, s
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
// film: 1968 x 4 samples spanning y/z in [0.0693687926, 0.08948454185] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 485.6632457, 6114.611914>
  right <0, 123, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 16393.933
  pigment { function { max(0.002, min(0.98, 0.0274142 * (1 + 0.0319971 * ((y / 16393.933) - 0.07942666722) / 0.01005787462 + 0.104475 * sin(20.719227 * ((y / 16393.933) - 0.07942666722) / 0.01005787462 + 0.540458)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 318.0618877, 3903.354805> + 117101 * <0.5267892268, 0.4207962813, -0.7385279955> color rgb FL }
light_source { <0, 318.0618877, 3903.354805> + 117101 * <-0.6683415372, -0.4103675988, -0.6204176202> color rgb FL * 0.2097 }


// ball 0: pingpong
#declare C0_0 = <0, 318.0618877, 3903.354805>;  // mm
#declare V_0 = <-2001.659357, 0.9318615473, 109.3484705>;  // mm/s
#declare TC_0 = 0.016366832541491714;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.9627273333, 0.4332273, 0.04813636667> }
  finish { ambient 0.2124 diffuse 0.7876 phong 0.3 phong_size 40 } }
  no_shadow
  rotate <141.4062724, 305.5830202, 243.0235264>
  transform { Axis_Rotate_Trans(<0.5388312702, 0.7847597398, 0.3062891006>, 643.55374 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
