// validation scene pv0111 (seed 111)
#version 3.7;
#declare NS = 2;
#declare NLT = 33;
#declare LINES = array[33] { 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40 };
#declare LR = 267.6181812049991;  // line rate, Hz
#declare TAU = 0.0007126345026918002;  // exposure, s
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
// film: 3056 x 4 samples spanning y/z in [-0.03257088222, 0.03300056475] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 0.6258010657, 2912.853213>
  right <0, 191, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 26453.252
  pigment { function { max(0.002, min(0.98, 0.054364 * (1 + -0.318021 * ((y / 26453.252) - 0.0002148412639) / 0.03278572349 + 0.048395 * sin(7.1817547 * ((y / 26453.252) - 0.0002148412639) / 0.03278572349 + 1.92796)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 122.1764561, 7156.243281> + 214687 * <0.3782933824, 0.7060414971, -0.598664782> color rgb FL }
light_source { <0, 122.1764561, 7156.243281> + 214687 * <0.059287351, -0.0751730648, -0.9954064599> color rgb FL * 0.5776 }


// ball 0: plain
#declare C0_0 = <0, 122.1764561, 7156.243281>;  // mm
#declare V_0 = <1574.012182, 127.6719823, 328.5872673>;  // mm/s
#declare TC_0 = 0.08968000564063203;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.8288150327, 0.8179829899, 0.5031047309> }
  finish { ambient 0.1161 diffuse 0.8839 phong 0.6231 phong_size 40 } }
  no_shadow
  rotate <60.15933436, 169.0379551, 160.7152646>
  transform { Axis_Rotate_Trans(<-0.9055796423, -0.1110327844, -0.4093864095>, 174.91407 * (T - TC_0)) }
  scale 83.7564235
  translate P_0 }
#end
