// validation scene pv0148 (seed 148)
#version 3.7;
#declare NS = 9;
#declare NLT = 37;
#declare LINES = array[37] { 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44 };
#declare LR = 71.5140362943807;  // line rate, Hz
#declare TAU = 0.010565000442810623;  // exposure, s
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
// film: 1968 x 4 samples spanning y/z in [-0.006010639289, 0.008009764607] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 8.76909167, 8772.928434>
  right <0, 123, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 9268.319
  pigment { function { max(0.002, min(0.98, 0.0251296 * (1 + 0.0408498 * ((y / 9268.319) - 0.0009995626587) / 0.007010201948 + 0.107557 * sin(23.488677 * ((y / 9268.319) - 0.0009995626587) / 0.007010201948 + 3.99416)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -1.172223586, 4411.0615> + 132332 * <0.3770184429, -0.6896198027, -0.61828927> color rgb FL }


// ball 0: pingpong
#declare C0_0 = <0, -1.172223586, 4411.0615>;  // mm
#declare V_0 = <-91.96211063, -29.53709499, 33.22332031>;  // mm/s
#declare TC_0 = 0.36356499153499716;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.7625983524, 0.3431692586, 0.03812991762> }
  finish { ambient 0.4933 diffuse 0.5067 phong 0.4704 phong_size 40 } }
  no_shadow
  rotate <108.5942379, 166.1518702, 254.5215817>
  transform { Axis_Rotate_Trans(<-0.5848081379, 0.1813563527, 0.790638549>, 81.775547 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
