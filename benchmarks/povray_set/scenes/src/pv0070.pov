// validation scene pv0070 (seed 70)
#version 3.7;
#declare NS = 1;
#declare NLT = 179;
#declare LINES = array[179] { 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214, 215, 216, 217, 218, 219, 220, 221, 222, 223, 224, 225, 226, 227, 228, 229, 230 };
#declare LR = 27459.757994359035;  // line rate, Hz
#declare TAU = 2.2260726865678966e-06;  // exposure, s
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
// film: 524 x 4 samples spanning y/z in [0.199783148, 0.2436228059] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 662.4844113, 2988.162001>
  right <0, 131, 0>
  up <1, 0, 0>
  aperture 16.862346 blur_samples 19 focal_point <0, 503.3986078, 2270.5992> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 7838.4749
  pigment { function { max(0.002, min(0.98, 0.822942 * (1 + 0.0767338 * ((y / 7838.4749) - 0.2217029769) / 0.02191982897 + 0.20952 * sin(19.048387 * ((y / 7838.4749) - 0.2217029769) / 0.02191982897 + 3.35527)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 416.7673501, 1845.607396> + 55368.2 * <-0.1999033595, 0.06910556671, -0.9773756021> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, 416.7673501, 1845.607396>;  // mm
#declare V_0 = <5047.691721, 816.1713239, -1279.454699>;  // mm/s
#declare TC_0 = 0.005134786695096335;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.0767164926, 0.09446307349, 0.08435439905> }
  finish { ambient 0.3348 diffuse 0.6652 } }
  no_shadow
  rotate <145.9077542, 228.6254073, 14.42231437>
  transform { Axis_Rotate_Trans(<0.3119060449, -0.05501583862, 0.9485187803>, 722.81413 * (T - TC_0)) }
  scale 15.85136938
  translate P_0 }
#end
