// validation scene pv3137 (seed 3137)
#version 3.7;
#declare NS = 2;
#declare NLT = 115;
#declare LINES = array[115] { 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146 };
#declare LR = 494.58151527046925;  // line rate, Hz
#declare TAU = 0.0016445850879909976;  // exposure, s
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
// film: 392 x 4 samples spanning y/z in [-0.01285131934, 0.01466128427] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 3.223551028, 3562.00385>
  right <0, 98, 0>
  up <1, 0, 0>
  aperture 6.6257282 blur_samples 19 focal_point <0, 3.621456437, 4001.6869> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 8243.2689
  pigment { function { max(0.002, min(0.98, 0.0712621 * (1 + -0.201547 * ((y / 8243.2689) - 0.0009049824658) / 0.01375630181 + 0 * sin(7.5041146 * ((y / 8243.2689) - 0.0009049824658) / 0.01375630181 + 5.80258)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -26.91985688, 2774.620061> + 83238.6 * <0.2347109407, 0.007831401164, -0.9720336637> color rgb FL }
light_source { <0, -26.91985688, 2774.620061> + 83238.6 * <-0.5648170076, 0.5224783039, -0.6387473443> color rgb FL * 0.4602 }


// ball 0: pingpong
#declare C0_0 = <0, -26.91985688, 2774.620061>;  // mm
#declare V_0 = <-182.9660866, -22.20109312, -71.96872114>;  // mm/s
#declare TC_0 = 0.17995011388836282;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.7424450221, 0.7424450221, 0.7424450221> }
  finish { ambient 0.2578 diffuse 0.7422 phong 0.6726 phong_size 40 } }
  no_shadow
  rotate <28.97617929, 47.47409196, 166.216774>
  transform { Axis_Rotate_Trans(<-0.8020795825, 0.1415988498, -0.5801879946>, 132.46504 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
