// validation scene pv0138 (seed 138)
#version 3.7;
#declare NS = 1;
#declare NLT = 151;
#declare LINES = array[151] { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150 };
#declare LR = 3006.9129723888864;  // line rate, Hz
#declare TAU = 0.00012108721902972494;  // exposure, s
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
// film: 448 x 4 samples spanning y/z in [-0.0326034935, 0.0264871862] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -5.796399873, 1895.391973>
  right <0, 112, 0>
  up <1, 0, 0>
  aperture 20.425267 blur_samples 19 focal_point <0, -6.170113428, 2017.5943> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 13465.789
  pigment { function { max(0.002, min(0.98, 0.624993 * (1 + 0.387057 * ((y / 13465.789) - -0.003058153645) / 0.02954533985 + 0 * sin(6.4092112 * ((y / 13465.789) - -0.003058153645) / 0.02954533985 + 4.85614)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 32.57872268, 3142.492255> + 94274.8 * <-0.9840713418, -0.1702808226, 0.05106893121> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, 32.57872268, 3142.492255>;  // mm
#declare V_0 = <1076.050165, -1315.88665, -287.6066497>;  // mm/s
#declare TC_0 = 0.021949421418593743;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.2122232578, 0.2147313117, 0.2557528919> }
  finish { ambient 0.2069 diffuse 0.7931 phong 0.672 phong_size 40 } }
  no_shadow
  rotate <223.5908822, 86.17495173, 314.5027473>
  transform { Axis_Rotate_Trans(<-0.5104959019, 0.5037202245, -0.6968930115>, 98.941419 * (T - TC_0)) }
  scale 28.61727783
  translate P_0 }
#end
