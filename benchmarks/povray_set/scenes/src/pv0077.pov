// validation scene pv0077 (seed 77)
#version 3.7;
#declare NS = 1;
#declare NLT = 43;
#declare LINES = array[43] { 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53 };
#declare LR = 291.8304048236626;  // line rate, Hz
#declare TAU = 0.001097993809009738;  // exposure, s
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
// film: 672 x 4 samples spanning y/z in [-0.03837331997, 0.02943240021] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -11.07422283, 2477.199915>
  right <0, 167.9683242, 0>
  up <1, 0, 0>
  aperture 25.152875 blur_samples 19 focal_point <0, -20.67280891, 4624.3137> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 12018.457
  pigment { function { max(0.002, min(0.98, 0.580892 * (1 + 0.0693189 * ((y / 12018.457) - -0.00447045988) / 0.03390286009 + 0 * sin(16.711697 * ((y / 12018.457) - -0.00447045988) / 0.03390286009 + 3.01237)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -27.95783303, 3395.863272> + 101876 * <0.549839364, 0.3910428095, -0.7380800735> color rgb FL }
light_source { <0, -27.95783303, 3395.863272> + 101876 * <0.6637722365, 0.441492562, -0.6037306815> color rgb FL * 0.5328 }


// ball 0: pingpong
#declare C0_0 = <0, -27.95783303, 3395.863272>;  // mm
#declare V_0 = <-305.0358324, 2.707297348, 2.183415178>;  // mm/s
#declare TC_0 = 0.10965272799225932;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.09307891654, 0.04188551244, 0.004653945827> }
  finish { ambient 0.2381 diffuse 0.7619 phong 0.3 phong_size 40 } }
  no_shadow
  rotate <69.00902341, 141.8172161, 244.6833054>
  transform { Axis_Rotate_Trans(<-0.8012301358, -0.5344306167, -0.2690988394>, 72.597325 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
