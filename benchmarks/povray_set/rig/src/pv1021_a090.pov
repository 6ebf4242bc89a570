// validation scene pv1021_a090 (seed 1021)
#version 3.7;
#declare NS = 1;
#declare NLT = 125;
#declare LINES = array[125] { 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159 };
#declare LR = 2752.7797893402194;  // line rate, Hz
#declare TAU = 5.926509969548704e-05;  // exposure, s
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
// film: 1888 x 4 samples spanning y/z in [0.2733374314, 0.3843751206] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 349.4762981, 1062.702231>
  right <0, 118, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 34061.834
  pigment { function { max(0.002, min(0.98, 0.0279933 * (1 + 0.331005 * ((y / 34061.834) - 0.328856276) / 0.05551884459 + 0 * sin(7.6393314 * ((y / 34061.834) - 0.328856276) / 0.05551884459 + 3.47688)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 1796.71062, 6110.734219> + 183322 * <0.1546963789, 0.9689475127, 0.192898284> color rgb FL }
light_source { <0, 1796.71062, 6110.734219> + 183322 * <-0.4528055383, 0.8693603596, -0.197938651> color rgb FL * 0.647 }


// ball 0: golf
#declare C0_0 = <0, 1796.71062, 6110.734219>;  // mm
#declare V_0 = <-1107.249872, -195.4776969, 31.74277337>;  // mm/s
#declare TC_0 = 0.035237108458736816;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.8875750482, 0.8875750482, 0.8875750482> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.4707 diffuse 0.5293 phong 0.3678 phong_size 40 } }
  no_shadow
  rotate <338.8709552, 236.5948213, 216.463799>
  transform { Axis_Rotate_Trans(<0.06453370829, 0.9951865613, -0.07375031269>, 148.79301 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
