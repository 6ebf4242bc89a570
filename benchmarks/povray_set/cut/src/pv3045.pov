// validation scene pv3045 (seed 3045)
#version 3.7;
#declare NS = 1;
#declare NLT = 69;
#declare LINES = array[69] { 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104 };
#declare LR = 1850.9359217920537;  // line rate, Hz
#declare TAU = 0.00015895879633013086;  // exposure, s
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
// film: 376 x 4 samples spanning y/z in [-0.03063725705, 0.03325219615] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 1.923783325, 1471.379066>
  right <0, 94.005604, 0>
  up <1, 0, 0>
  aperture 6.6601033 blur_samples 19 focal_point <0, 0.9528851647, 728.80104> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 6237.7
  pigment { function { max(0.002, min(0.98, 0.752335 * (1 + 0.0768204 * ((y / 6237.7) - 0.001307469549) / 0.0319447266 + 0.0717911 * sin(19.152438 * ((y / 6237.7) - 0.001307469549) / 0.0319447266 + 5.39221)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -6.953017855, 1101.998523> + 33060 * <-0.6350117104, -0.5433410061, -0.5491271972> color rgb FL }


// ball 0: golf
#declare C0_0 = <0, -6.953017855, 1101.998523>;  // mm
#declare V_0 = <662.8421545, -233.225708, 309.6515719>;  // mm/s
#declare TC_0 = 0.05294618730243108;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.1257456573, 0.1257456573, 0.1257456573> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.2462 diffuse 0.7538 phong 0.35 phong_size 40 } }
  no_shadow
  rotate <234.8836774, 107.8665143, 162.5503231>
  transform { Axis_Rotate_Trans(<0.6079039284, 0.2121937636, 0.7651317667>, 0 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
