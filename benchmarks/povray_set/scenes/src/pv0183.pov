// validation scene pv0183 (seed 183)
#version 3.7;
#declare NS = 1;
#declare NLT = 39;
#declare LINES = array[39] { 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47 };
#declare LR = 143.82724978944458;  // line rate, Hz
#declare TAU = 0.001091823248183804;  // exposure, s
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
// film: 2336 x 4 samples spanning y/z in [-0.04695116688, 0.09236368028] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 23.7958376, 1047.985932>
  right <0, 146, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 10770.05
  pigment { function { max(0.002, min(0.98, 0.185544 * (1 + 0.259462 * ((y / 10770.05) - 0.0227062567) / 0.06965742358 + 0 * sin(17.705867 * ((y / 10770.05) - 0.0227062567) / 0.06965742358 + 3.17993)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 153.1793275, 4656.331844> + 139690 * <-0.210728026, -0.06108678154, -0.9756342061> color rgb FL }


// ball 0: golf
#declare C0_0 = <0, 153.1793275, 4656.331844>;  // mm
#declare V_0 = <-199.0843598, -234.6947264, -7.273567151>;  // mm/s
#declare TC_0 = 0.1946779907214419;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.9071739689, 0.9071739689, 0.9071739689> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.2645 diffuse 0.7355 phong 0.35 phong_size 40 } }
  no_shadow
  rotate <144.8777978, 314.4341077, 146.4232442>
  transform { Axis_Rotate_Trans(<-0.8734907811, 0.4309274115, -0.2265290741>, 18.499667 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
