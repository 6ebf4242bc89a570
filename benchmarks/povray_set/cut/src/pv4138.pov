// validation scene pv4138 (seed 4138)
#version 3.7;
#declare NS = 1;
#declare NLT = 72;
#declare LINES = array[72] { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71 };
#declare LR = 106807.69353556429;  // line rate, Hz
#declare TAU = 1.98683040269769e-06;  // exposure, s
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
// film: 1616 x 4 samples spanning y/z in [0.03646135339, 0.1351083619] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 87.83105289, 1023.852639>
  right <0, 101, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 6291.3282
  pigment { function { max(0.002, min(0.98, 0.0570247 * (1 + 0.396248 * ((y / 6291.3282) - 0.08578485764) / 0.04932350425 + 0 * sin(16.377287 * ((y / 6291.3282) - 0.08578485764) / 0.04932350425 + 2.56683)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 195.1006067, 1818.33028> + 54549.9 * <-0.5445021869, 0.2218722127, -0.8088819999> color rgb FL }
light_source { <0, 195.1006067, 1818.33028> + 54549.9 * <-0.6637158311, 0.7438812701, -0.07824290032> color rgb FL * 0.6236 }


// ball 0: pingpong
#declare C0_0 = <0, 195.1006067, 1818.33028>;  // mm
#declare V_0 = <27320.87938, 32831.63497, 1161.870612>;  // mm/s
#declare TC_0 = -0.00011235145711675067;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.8285127474, 0.8285127474, 0.8285127474> }
  finish { ambient 0.4426 diffuse 0.5574 phong 0.3 phong_size 40 } }
  no_shadow
  rotate <227.4648303, 252.6221175, 136.9289584>
  transform { Axis_Rotate_Trans(<0.6944106161, -0.7031531484, -0.1528710112>, 0 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
