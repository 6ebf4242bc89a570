// validation scene pv1089_a090 (seed 1089)
#version 3.7;
#declare NS = 1;
#declare NLT = 133;
#declare LINES = array[133] { 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170 };
#declare LR = 5448.434002977055;  // line rate, Hz
#declare TAU = 7.402636181677958e-05;  // exposure, s
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
// film: 1344 x 4 samples spanning y/z in [0.07897188426, 0.1695489051] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 116.0900986, 934.2485904>
  right <0, 84.62145404, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 5799.1556
  pigment { function { max(0.002, min(0.98, 0.0287607 * (1 + -0.213185 * ((y / 5799.1556) - 0.1242603947) / 0.04528851042 + 0.0757392 * sin(19.015447 * ((y / 5799.1556) - 0.1242603947) / 0.04528851042 + 1.9288)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 310.9810291, 2275.105256> + 68253.2 * <0.1787223061, 0.7922568767, 0.5834272693> color rgb FL }
light_source { <0, 310.9810291, 2275.105256> + 68253.2 * <-0.4445439903, 0.8957465202, -0.004337305601> color rgb FL * 0.3238 }


// ball 0: golf
#declare C0_0 = <0, 310.9810291, 2275.105256>;  // mm
#declare V_0 = <-1913.609078, -11.31850387, -51.67739651>;  // mm/s
#declare TC_0 = 0.019088053547711842;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.6620619784, 0.6620619784, 0.6620619784> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.308 diffuse 0.692 phong 0.35 phong_size 40 } }
  no_shadow
  rotate <146.0088852, 31.34292712, 207.2040025>
  transform { Axis_Rotate_Trans(<-0.1446382202, -0.2555341398, 0.955919499>, 0 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
