// validation scene pu2012 (seed 2012)
#version 3.7;
#declare NS = 1;
#declare NLT = 135;
#declare LINES = array[135] { 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173 };
#declare LR = 807.4496376164793;  // line rate, Hz
#declare TAU = 0.00013518585958200108;  // exposure, s
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
// film: 336 x 4 samples spanning y/z in [-0.01481519121, 0.01412223565] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -1.005810726, 2902.958817>
  right <0, 84.00415842, 0>
  up <1, 0, 0>
  aperture 38.850619 blur_samples 19 focal_point <0, -2.522632924, 7280.7928> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 26221.604
  pigment { function { max(0.002, min(0.98, 0.686552 * (1 + -0.261763 * ((y / 26221.604) - -0.00034647778) / 0.01446871343 + 0.0284951 * sin(8.4839471 * ((y / 26221.604) - -0.00034647778) / 0.01446871343 + 3.53332)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -3.921153712, 11516.61624> + 345498 * <-0.5117480672, -0.6856049351, -0.5177449069> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, -3.921153712, 11516.61624>;  // mm
#declare V_0 = <-1371.986106, 183.0272467, 9.042181718>;  // mm/s
#declare TC_0 = 0.13127753739899212;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.2162523622, 0.2162523622, 0.2162523622> }
  finish { ambient 1 diffuse 0 } }
  no_shadow
  rotate <124.1997041, 319.5993848, 338.8653435>
  transform { Axis_Rotate_Trans(<-0.7866450366, 0.5275992841, -0.3206689598>, 69.401192 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
