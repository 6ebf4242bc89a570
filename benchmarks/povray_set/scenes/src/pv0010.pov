// validation scene pv0010 (seed 10)
#version 3.7;
#declare NS = 1;
#declare NLT = 35;
#declare LINES = array[35] { 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42 };
#declare LR = 69.64034317665335;  // line rate, Hz
#declare TAU = 0.00047240176128598624;  // exposure, s
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
// film: 2016 x 4 samples spanning y/z in [-0.171294566, -0.0953819928] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -224.0592279, 1680.381875>
  right <0, 127.562112, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 9805.4347
  pigment { function { max(0.002, min(0.98, 0.0109683 * (1 + 0.277807 * ((y / 9805.4347) - -0.1333382794) / 0.03795628658 + 0 * sin(5.0755794 * ((y / 9805.4347) - -0.1333382794) / 0.03795628658 + 5.00761)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -548.644936, 3246.951377> + 97408.5 * <0.2332178315, 0.455847102, -0.8589603382> color rgb FL }


// ball 0: pingpong
#declare C0_0 = <0, -548.644936, 3246.951377>;  // mm
#declare V_0 = <97.18451965, -59.30815147, 10.40183156>;  // mm/s
#declare TC_0 = 0.35898731769003045;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.6844633742, 0.6844633742, 0.6844633742> }
  finish { ambient 0.5391 diffuse 0.4609 phong 0.3 phong_size 40 } }
  no_shadow
  rotate <209.2692606, 117.4281328, 214.1538276>
  transform { Axis_Rotate_Trans(<0.8135470697, -0.08078111759, 0.5758607265>, 66.455412 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
