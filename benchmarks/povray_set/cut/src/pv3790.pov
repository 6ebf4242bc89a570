// validation scene pv3790 (seed 3790)
#version 3.7;
#declare NS = 1;
#declare NLT = 99;
#declare LINES = array[99] { 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133 };
#declare LR = 2158.6142370182697;  // line rate, Hz
#declare TAU = 7.961086562685441e-05;  // exposure, s
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
// film: 312 x 4 samples spanning y/z in [-0.3824730457, -0.3550619603] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -1049.351563, 2845.564087>
  right <0, 78, 0>
  up <1, 0, 0>
  aperture 17.274667 blur_samples 19 focal_point <0, -2324.964489, 6304.6892> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 16171.203
  pigment { function { max(0.002, min(0.98, 0.0640825 * (1 + -0.0740729 * ((y / 16171.203) - -0.368767503) / 0.01370554266 + 0.00467484 * sin(12.541912 * ((y / 16171.203) - -0.368767503) / 0.01370554266 + 4.96087)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -1718.13747, 4647.431198> + 139423 * <-0.4231973829, -0.2742211814, -0.8635431192> color rgb FL }


// ball 0: pingpong
#declare C0_0 = <0, -1718.13747, 4647.431198>;  // mm
#declare V_0 = <744.7332392, 7.377041757, -67.02814913>;  // mm/s
#declare TC_0 = 0.044936236561650654;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.8738969383, 0.8738969383, 0.8738969383> }
  finish { ambient 0.3028 diffuse 0.6972 phong 0.3 phong_size 40 } }
  no_shadow
  rotate <278.8671297, 85.50692079, 57.62146977>
  transform { Axis_Rotate_Trans(<-0.8428681282, -0.04165676548, -0.5365053889>, 0 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
