// validation scene pv0022 (seed 22)
#version 3.7;
#declare NS = 3;
#declare NLT = 18;
#declare LINES = array[18] { 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26 };
#declare LR = 65.85355187088977;  // line rate, Hz
#declare TAU = 0.005380067935174618;  // exposure, s
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
// film: 1120 x 4 samples spanning y/z in [-0.00977430152, 0.01148548777] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 2.817126635, 3292.600837>
  right <0, 70, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 26737.478
  pigment { function { max(0.002, min(0.98, 0.540647 * (1 + 0.0502497 * ((y / 26737.478) - 0.0008555931237) / 0.01062989464 + 0 * sin(8.2475771 * ((y / 26737.478) - 0.0008555931237) / 0.01062989464 + 1.31865)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 10.9902198, 4849.735779> + 145492 * <-0.4857397951, 0.1129944087, -0.8667693552> color rgb FL }
light_source { <0, 10.9902198, 4849.735779> + 145492 * <0.06980177327, 0.9695442554, 0.2347587044> color rgb FL * 0.2721 }


// ball 0: plain
#declare C0_0 = <0, 10.9902198, 4849.735779>;  // mm
#declare V_0 = <-144.069577, -16.48855051, -15.83525637>;  // mm/s
#declare TC_0 = 0.41000066409379526;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.07359324969, 0.04506206771, 0.08104610594> }
  finish { ambient 0.1534 diffuse 0.8466 phong 0.6515 phong_size 40 } }
  no_shadow
  rotate <11.31416586, 171.9565147, 25.28473409>
  transform { Axis_Rotate_Trans(<-0.3478369005, 0.6599118624, -0.6659773453>, 0 * (T - TC_0)) }
  scale 35.22166729
  translate P_0 }
#end
