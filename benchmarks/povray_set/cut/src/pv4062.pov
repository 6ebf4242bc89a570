// validation scene pv4062 (seed 4062)
#version 3.7;
#declare NS = 1;
#declare NLT = 123;
#declare LINES = array[123] { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122 };
#declare LR = 20025.137440213868;  // line rate, Hz
#declare TAU = 1.1379428159673073e-05;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.245916 * sin(753.9822369 * T + 4.26847));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 1744 x 4 samples spanning y/z in [0.1075403543, 0.1194205907] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 1041.267216, 9175.739163>
  right <0, 109.0099503, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 24239.257
  pigment { function { max(0.002, min(0.98, 0.0815523 * (1 + 0.02275 * ((y / 24239.257) - 0.1134804725) / 0.005940118197 + 0.013949 * sin(22.153932 * ((y / 24239.257) - 0.1134804725) / 0.005940118197 + 2.84559)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 1097.467462, 9672.868321> + 290186 * <0.1919311816, 0.05358277093, -0.9799445434> color rgb FL }


// ball 0: pingpong
#declare C0_0 = <0, 1097.467462, 9672.868321>;  // mm
#declare V_0 = <-5041.250123, -868.5586673, -207.1223978>;  // mm/s
#declare TC_0 = 0.0019475521761803938;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.723505006, 0.3255772527, 0.0361752503> }
  finish { ambient 0.2399 diffuse 0.7601 phong 0.3 phong_size 40 } }
  no_shadow
  rotate <246.5689655, 340.4387549, 300.4731673>
  transform { Axis_Rotate_Trans(<0.5789792273, -0.6369501871, -0.5089965752>, 1785.2128 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
