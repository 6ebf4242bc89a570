// validation scene pv0285 (seed 285)
#version 3.7;
#declare NS = 1;
#declare NLT = 43;
#declare LINES = array[43] { 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53 };
#declare LR = 8530.665415472431;  // line rate, Hz
#declare TAU = 4.9552072528645615e-05;  // exposure, s
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
// film: 328 x 4 samples spanning y/z in [-0.1874365269, -0.0912550969] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -118.800028, 852.5554255>
  right <0, 82, 0>
  up <1, 0, 0>
  aperture 103.42288 blur_samples 19 focal_point <0, -953.5111204, 6842.7684> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 12114.659
  pigment { function { max(0.002, min(0.98, 0.051341 * (1 + 0.075256 * ((y / 12114.659) - -0.1393458119) / 0.04809071501 + 0.248305 * sin(19.34888 * ((y / 12114.659) - -0.1393458119) / 0.04809071501 + 2.47871)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -699.3387622, 4786.430479> + 143593 * <-0.2559680264, -0.791819345, -0.5545290743> color rgb FL }
light_source { <0, -699.3387622, 4786.430479> + 143593 * <-0.3529744619, -0.675999222, -0.646864809> color rgb FL * 0.2137 }


// ball 0: golf
#declare C0_0 = <0, -699.3387622, 4786.430479>;  // mm
#declare V_0 = <10655.96342, 2110.09996, -70.44130754>;  // mm/s
#declare TC_0 = 0.0037511727915105235;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.8115432209, 0.8115432209, 0.8115432209> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.3256 diffuse 0.6744 phong 0.2011 phong_size 40 } }
  no_shadow
  rotate <233.232209, 326.5306132, 185.3618679>
  transform { Axis_Rotate_Trans(<-0.1155934984, -0.5701870836, 0.8133417688>, 7373.0469 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
