// validation scene pv3123 (seed 3123)
#version 3.7;
#declare NS = 1;
#declare NLT = 112;
#declare LINES = array[112] { 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159 };
#declare LR = 215193.64418520354;  // line rate, Hz
#declare TAU = 6.608755118459233e-07;  // exposure, s
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
// film: 376 x 4 samples spanning y/z in [-0.009774213617, 0.01415019169] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 8.596701432, 3929.042281>
  right <0, 94, 0>
  up <1, 0, 0>
  aperture 9.5512805 blur_samples 19 focal_point <0, 4.38478201, 2004.0238> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 14182.35
  pigment { function { max(0.002, min(0.98, 0.641276 * (1 + 0.369965 * ((y / 14182.35) - 0.002187989035) / 0.01196220265 + 0.00235322 * sin(22.828751 * ((y / 14182.35) - 0.002187989035) / 0.01196220265 + 4.3049)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 3.540840695, 3046.560666> + 91396.8 * <0.4113385892, 0.2690737616, -0.870861571> color rgb FL }
light_source { <0, 3.540840695, 3046.560666> + 91396.8 * <-0.002435157317, -0.3703017148, -0.9289083432> color rgb FL * 0.3806 }


// ball 0: pingpong
#declare C0_0 = <0, 3.540840695, 3046.560666>;  // mm
#declare V_0 = <53304.44162, -25794.91368, -4249.023141>;  // mm/s
#declare TC_0 = 0.0006134010160931889;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.2192836576, 0.09867764591, 0.01096418288> }
  finish { ambient 0.4016 diffuse 0.5984 phong 0.3 phong_size 40 } }
  no_shadow
  rotate <64.60479428, 155.1956709, 70.60894557>
  transform { Axis_Rotate_Trans(<-0.557495892, 0.7630622183, 0.3270082282>, 2344.4591 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
