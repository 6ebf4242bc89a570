// validation scene pv0267 (seed 267)
#version 3.7;
#declare NS = 1;
#declare NLT = 49;
#declare LINES = array[49] { 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60 };
#declare LR = 20.0;  // line rate, Hz
#declare TAU = 0.0031778160942607103;  // exposure, s
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
// film: 2208 x 4 samples spanning y/z in [0.1805201003, 0.2346391394] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 518.7056471, 2498.827426>
  right <0, 135.2341392, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 53276.479
  pigment { function { max(0.002, min(0.98, 0.103341 * (1 + -0.161781 * ((y / 53276.479) - 0.2075796198) / 0.02705951955 + 0.235939 * sin(13.810338 * ((y / 53276.479) - 0.2075796198) / 0.02705951955 + 3.83494)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 3316.159295, 14825.33549> + 444760 * <-0.04035620255, 0.5194327509, -0.8535578447> color rgb FL }
light_source { <0, 3316.159295, 14825.33549> + 444760 * <0.6090144321, -0.792969515, 0.01734271654> color rgb FL * 0.2019 }


// ball 0: plain
#declare C0_0 = <0, 3316.159295, 14825.33549>;  // mm
#declare V_0 = <57.33632741, 4.967340263, 15.35134624>;  // mm/s
#declare TC_0 = 1.8;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.5319928376, 0.2977113865, 0.3369144111> }
  finish { ambient 0.3208 diffuse 0.6792 } }
  no_shadow
  rotate <65.16827734, 81.81997767, 340.7667292>
  transform { Axis_Rotate_Trans(<-0.5213985682, 0.6380866171, 0.5665589132>, 51.274237 * (T - TC_0)) }
  scale 60.21797591
  translate P_0 }
#end
