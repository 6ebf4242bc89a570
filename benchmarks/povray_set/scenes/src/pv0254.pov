// validation scene pv0254 (seed 254)
#version 3.7;
#declare NS = 1;
#declare NLT = 127;
#declare LINES = array[127] { 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162 };
#declare LR = 368.9980301173175;  // line rate, Hz
#declare TAU = 0.0003025953253835668;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.0996354 * sin(628.3185307 * T + 1.93116));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 2512 x 4 samples spanning y/z in [0.004187656862, 0.05693921734] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 90.93339987, 2975.234741>
  right <0, 156.9482754, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 3584.2711
  pigment { function { max(0.002, min(0.98, 0.183931 * (1 + -0.0815552 * ((y / 3584.2711) - 0.0305634371) / 0.02637578024 + 0 * sin(14.127455 * ((y / 3584.2711) - 0.0305634371) / 0.02637578024 + 5.66694)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 36.8893324, 1715.643814> + 51469.3 * <-0.4531092997, -0.2706420932, -0.8493790791> color rgb FL }


// ball 0: pingpong
#declare C0_0 = <0, 36.8893324, 1715.643814>;  // mm
#declare V_0 = <-121.5994839, -19.1148458, 12.26586472>;  // mm/s
#declare TC_0 = 0.2682941151976459;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.7855391278, 0.3534926075, 0.03927695639> }
  finish { ambient 0.2955 diffuse 0.7045 phong 0.4719 phong_size 40 } }
  no_shadow
  rotate <89.71367487, 149.2933379, 284.8205406>
  transform { Axis_Rotate_Trans(<0.7027791968, 0.3252715005, -0.6326925411>, 43.603014 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
