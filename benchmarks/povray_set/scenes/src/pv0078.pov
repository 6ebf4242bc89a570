// validation scene pv0078 (seed 78)
#version 3.7;
#declare NS = 1;
#declare NLT = 95;
#declare LINES = array[95] { 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120 };
#declare LR = 32.59665985338718;  // line rate, Hz
#declare TAU = 0.005159755383058381;  // exposure, s
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
// film: 528 x 4 samples spanning y/z in [-0.05514453518, 0.05298331537] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -1.31918379, 1220.777065>
  right <0, 132, 0>
  up <1, 0, 0>
  aperture 83.990245 blur_samples 19 focal_point <0, -8.406501406, 7779.4043> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 22966.391
  pigment { function { max(0.002, min(0.98, 0.205643 * (1 + 0.322573 * ((y / 22966.391) - -0.001080609907) / 0.05406392528 + 0 * sin(10.981706 * ((y / 22966.391) - -0.001080609907) / 0.05406392528 + 3.04205)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -72.98317771, 4942.976752> + 148289 * <0.1911541511, -0.2514298189, -0.9488114337> color rgb FL }
light_source { <0, -72.98317771, 4942.976752> + 148289 * <0.1998081639, -0.4067974646, -0.8913991925> color rgb FL * 0.4135 }


// ball 0: plain
#declare C0_0 = <0, -72.98317771, 4942.976752>;  // mm
#declare V_0 = <76.5780036, 77.38896123, 7.725113914>;  // mm/s
#declare TC_0 = 2.2394932587675678;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.8632298871, 0.3819682944, 0.2236157166> }
  finish { ambient 0.3479 diffuse 0.6521 } }
  no_shadow
  rotate <137.1071345, 24.42192623, 29.65621951>
  transform { Axis_Rotate_Trans(<0.8474905385, -0.5244573634, -0.08187955182>, 62.148151 * (T - TC_0)) }
  scale 103.8217212
  translate P_0 }
#end
