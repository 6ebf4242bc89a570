// validation scene pv1029_a030 (seed 1029)
#version 3.7;
#declare NS = 2;
#declare NLT = 71;
#declare LINES = array[71] { 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89 };
#declare LR = 22262.09515976179;  // line rate, Hz
#declare TAU = 1.5211364530741153e-05;  // exposure, s
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
// film: 384 x 4 samples spanning y/z in [0.1712075836, 0.2524244371] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 244.8222967, 1155.825267>
  right <0, 93.87249147, 0>
  up <1, 0, 0>
  aperture 12.822829 blur_samples 19 focal_point <0, 228.0720702, 1076.7461> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 2016.7835
  pigment { function { max(0.002, min(0.98, 0.0726583 * (1 + -0.382201 * ((y / 2016.7835) - 0.2118160103) / 0.04060842679 + 0.205342 * sin(21.947431 * ((y / 2016.7835) - 0.2118160103) / 0.04060842679 + 3.67968)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 165.0572841, 782.6243206> + 23478.7 * <0.6929364824, 0.5824986651, -0.4248933237> color rgb FL }


// ball 0: pingpong
#declare C0_0 = <0, 165.0572841, 782.6243206>;  // mm
#declare V_0 = <-13561.79343, -1301.977055, -2620.454606>;  // mm/s
#declare TC_0 = 0.0024256477035280903;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.7968734165, 0.7968734165, 0.7968734165> }
  finish { ambient 0.436 diffuse 0.564 phong 0.3 phong_size 40 } }
  no_shadow
  rotate <252.1727305, 308.7876885, 304.9849242>
  transform { Axis_Rotate_Trans(<-0.9088262258, 0.306478288, 0.2830299458>, 5220.0158 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
