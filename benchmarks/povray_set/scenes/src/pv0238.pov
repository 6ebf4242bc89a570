// validation scene pv0238 (seed 238)
#version 3.7;
#declare NS = 1;
#declare NLT = 59;
#declare LINES = array[59] { 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74 };
#declare LR = 381.5104495309904;  // line rate, Hz
#declare TAU = 0.00013634326693495524;  // exposure, s
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
// film: 328 x 4 samples spanning y/z in [-0.06106220715, -0.00898154611] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -55.14127176, 1574.480784>
  right <0, 82, 0>
  up <1, 0, 0>
  aperture 12.947668 blur_samples 19 focal_point <0, -124.0578071, 3542.2947> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 12686.914
  pigment { function { max(0.002, min(0.98, 0.0294767 * (1 + -0.335868 * ((y / 12686.914) - -0.03502187663) / 0.02604033052 + 0 * sin(23.222517 * ((y / 12686.914) - -0.03502187663) / 0.02604033052 + 5.30532)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -232.6237467, 5385.733401> + 161572 * <0.3410286958, -0.4183938431, -0.841811155> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, -232.6237467, 5385.733401>;  // mm
#declare V_0 = <-359.2551525, -612.1286542, -201.7649522>;  // mm/s
#declare TC_0 = 0.11795220826931666;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.6678330295, 0.1996289711, 0.5002336042> }
  finish { ambient 0.379 diffuse 0.621 } }
  no_shadow
  rotate <188.5381309, 138.00643, 137.3059434>
  transform { Axis_Rotate_Trans(<-0.3591104441, 0.9185767101, 0.1650954775>, 575.80533 * (T - TC_0)) }
  scale 24.60323126
  translate P_0 }
#end
