// validation scene pv0075 (seed 75)
#version 3.7;
#declare NS = 2;
#declare NLT = 101;
#declare LINES = array[101] { 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128 };
#declare LR = 633.724014651339;  // line rate, Hz
#declare TAU = 0.0011070117463379682;  // exposure, s
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
// film: 756 x 4 samples spanning y/z in [-0.1513000515, -0.1288893968] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -1162.768186, 8299.871344>
  right <0, 186.0055511, 0>
  up <1, 0, 0>
  aperture 25.847189 blur_samples 19 focal_point <0, -1087.500853, 7762.611> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 38954.977
  pigment { function { max(0.002, min(0.98, 0.0205371 * (1 + -0.312008 * ((y / 38954.977) - -0.1400947241) / 0.01120532737 + 0.234986 * sin(19.085298 * ((y / 38954.977) - -0.1400947241) / 0.01120532737 + 2.20772)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -1290.033138, 9159.729187> + 274792 * <0.3849309209, -0.2794274393, -0.8796297473> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, -1290.033138, 9159.729187>;  // mm
#declare V_0 = <182.4709704, 203.1152827, 22.75431175>;  // mm/s
#declare TC_0 = 0.1230819697481622;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.2135088139, 0.2358581743, 0.8289422204> }
  finish { ambient 0.5958 diffuse 0.4042 } }
  no_shadow
  rotate <0.9461412726, 24.58339628, 258.657371>
  transform { Axis_Rotate_Trans(<0.4996214409, 0.1013181879, -0.8602982277>, 0 * (T - TC_0)) }
  scale 13.31368769
  translate P_0 }
#end
