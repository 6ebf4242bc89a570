// validation scene pv0255 (seed 255)
#version 3.7;
#declare NS = 1;
#declare NLT = 51;
#declare LINES = array[51] { 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63 };
#declare LR = 3264.776212439721;  // line rate, Hz
#declare TAU = 1.7176525292822172e-05;  // exposure, s
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
// film: 316 x 4 samples spanning y/z in [-0.003586616195, 0.004021417322] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 2.257435441, 10383.76077>
  right <0, 79, 0>
  up <1, 0, 0>
  aperture 2.9386348 blur_samples 19 focal_point <0, 1.111125818, 5110.9611> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 31710.135
  pigment { function { max(0.002, min(0.98, 0.0487427 * (1 + -0.0529145 * ((y / 31710.135) - 0.0002174005633) / 0.003804016758 + 0 * sin(7.645593 * ((y / 31710.135) - 0.0002174005633) / 0.003804016758 + 0.214415)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 1.544155059, 7384.887497> + 221547 * <-0.704975879, 0.0779939569, -0.7049297502> color rgb FL }


// ball 0: pingpong
#declare C0_0 = <0, 1.544155059, 7384.887497>;  // mm
#declare V_0 = <2806.819121, 111.9724287, -1073.927193>;  // mm/s
#declare TC_0 = 0.011639388897532778;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.9333635399, 0.420013593, 0.046668177> }
  finish { ambient 0.105 diffuse 0.895 phong 0.3 phong_size 40 } }
  no_shadow
  rotate <106.3708866, 247.6453611, 145.2061378>
  transform { Axis_Rotate_Trans(<-0.168335686, 0.2007952044, -0.9650618543>, 0 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
