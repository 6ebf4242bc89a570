// validation scene pv0083 (seed 83)
#version 3.7;
#declare NS = 1;
#declare NLT = 67;
#declare LINES = array[67] { 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83 };
#declare LR = 58.79899099543253;  // line rate, Hz
#declare TAU = 0.0009151187830112413;  // exposure, s
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
// film: 2880 x 4 samples spanning y/z in [0.3599443582, 0.472904215] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 756.1231753, 1815.751865>
  right <0, 205.1070706, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 18200.127
  pigment { function { max(0.002, min(0.98, 0.127967 * (1 + 0.255302 * ((y / 18200.127) - 0.4164242866) / 0.05647992837 + 0 * sin(8.8905629 * ((y / 18200.127) - 0.4164242866) / 0.05647992837 + 3.65692)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 1679.684023, 4046.414506> + 121392 * <0.6341211597, 0.5664265443, -0.5263566517> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, 1679.684023, 4046.414506>;  // mm
#declare V_0 = <-149.2624061, -54.14246326, -40.70988034>;  // mm/s
#declare TC_0 = 0.8503547280919151;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.3324884339, 0.5842205039, 0.2083893343> }
  finish { ambient 0.4 diffuse 0.6 } }
  no_shadow
  rotate <201.8043442, 54.84604596, 349.3723116>
  transform { Axis_Rotate_Trans(<0.3592531373, 0.8207374071, 0.4442153666>, 0 * (T - TC_0)) }
  scale 78.03919991
  translate P_0 }
#end
