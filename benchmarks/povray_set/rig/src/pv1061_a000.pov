// validation scene pv1061_a000 (seed 1061)
#version 3.7;
#declare NS = 2;
#declare NLT = 125;
#declare LINES = array[125] { 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159 };
#declare LR = 41.70121790354313;  // line rate, Hz
#declare TAU = 0.008466508399082034;  // exposure, s
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
// film: 2432 x 4 samples spanning y/z in [0.3046837627, 0.3283065623] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 2055.06125, 6493.183764>
  right <0, 153.387179, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 65364.003
  pigment { function { max(0.002, min(0.98, 0.0363992 * (1 + 0.143349 * ((y / 65364.003) - 0.3164951625) / 0.01181139981 + 0.222823 * sin(8.5669032 * ((y / 65364.003) - 0.3164951625) / 0.01181139981 + 0.647345)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 3630.104671, 11596.76335> + 347903 * <-0.1632651391, -0.0001670822994, -0.9865822147> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, 3630.104671, 11596.76335>;  // mm
#declare V_0 = <-30.81566765, 47.74742618, 0.285212623>;  // mm/s
#declare TC_0 = 2.326071152750635;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.4008956146, 0.6479396552, 0.7971966487> }
  finish { ambient 0.4586 diffuse 0.5414 } }
  no_shadow
  rotate <12.19183246, 260.1694366, 151.1169778>
  transform { Axis_Rotate_Trans(<-0.1547078539, -0.02531537455, 0.98763587>, 38.25864 * (T - TC_0)) }
  scale 43.43339666
  translate P_0 }
#end
