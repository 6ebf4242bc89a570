// validation scene pu2010 (seed 2010)
#version 3.7;
#declare NS = 1;
#declare NLT = 86;
#declare LINES = array[86] { 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108 };
#declare LR = 520.1601433325527;  // line rate, Hz
#declare TAU = 0.0003894113728534221;  // exposure, s
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
// film: 2544 x 4 samples spanning y/z in [-0.01393798971, 0.02067591698] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 15.4754337, 4593.529458>
  right <0, 159, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 41996.772
  pigment { function { max(0.002, min(0.98, 0.178804 * (1 + -0.0836344 * ((y / 41996.772) - 0.003368963636) / 0.01730695334 + 0.247412 * sin(11.289817 * ((y / 41996.772) - 0.003368963636) / 0.01730695334 + 1.00717)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -32.8439227, 7806.015406> + 234180 * <-0.1159028559, -0.5779159714, -0.8078240266> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, -32.8439227, 7806.015406>;  // mm
#declare V_0 = <814.3243247, -466.2275989, -424.6141356>;  // mm/s
#declare TC_0 = 0.09035678838997782;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.5304343166, 0.6440988131, 0.1136644964> }
  finish { ambient 1 diffuse 0 } }
  no_shadow
  rotate <146.762744, 324.9484274, 282.4788792>
  transform { Axis_Rotate_Trans(<-0.3979579853, 0.3767829182, 0.8364592486>, 0 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
// ball 1: plain
#declare C0_1 = <0, 86.46113387, 7177.280373>;  // mm
#declare V_1 = <852.7800239, -36.22072385, 5.721143062>;  // mm/s
#declare TC_1 = 0.16363729364243979;  // s
#declare P_1 = C0_1 + V_1 * (T - TC_1);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.5304343166, 0.6440988131, 0.1136644964> }
  finish { ambient 1 diffuse 0 } }
  no_shadow
  rotate <195.7085988, 11.50259039, 145.3365699>
  transform { Axis_Rotate_Trans(<-0.3979579853, 0.3767829182, 0.8364592486>, 0 * (T - TC_1)) }
  scale 33.5
  translate P_1 }
#end
