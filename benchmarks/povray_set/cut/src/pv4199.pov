// validation scene pv4199 (seed 4199)
#version 3.7;
#declare NS = 1;
#declare NLT = 94;
#declare LINES = array[94] { 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141 };
#declare LR = 2070.51878849927;  // line rate, Hz
#declare TAU = 3.477910070073965e-05;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.151418 * sin(628.3185307 * T + 3.25913));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 1600 x 4 samples spanning y/z in [-0.03565014823, 0.06135574375] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 13.24602936, 1030.595019>
  right <0, 99.97378912, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 1850.7022
  pigment { function { max(0.002, min(0.98, 0.0882752 * (1 + -0.132281 * ((y / 1850.7022) - 0.01285279776) / 0.04850294599 + 0.0272946 * sin(12.8926 * ((y / 1850.7022) - 0.01285279776) / 0.04850294599 + 0.0772302)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 3.977868254, 524.7782239> + 15743.3 * <0.4000115619, 0.4664326832, -0.7889431553> color rgb FL }
light_source { <0, 3.977868254, 524.7782239> + 15743.3 * <0.6393377743, -0.7018019464, -0.3141993608> color rgb FL * 0.3086 }


// ball 0: pingpong
#declare C0_0 = <0, 3.977868254, 524.7782239>;  // mm
#declare V_0 = <-514.3332332, -47.40007404, 8.760335206>;  // mm/s
#declare TC_0 = 0.0632691674799773;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.8590311549, 0.3865640197, 0.04295155774> }
  finish { ambient 0.4717 diffuse 0.5283 phong 0.3 phong_size 40 } }
  no_shadow
  rotate <306.5347606, 68.46174527, 202.011522>
  transform { Axis_Rotate_Trans(<-0.436516725, 0.8975675903, -0.06185118923>, 30.687572 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
