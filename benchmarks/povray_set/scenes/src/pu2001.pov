// validation scene pu2001 (seed 2001)
#version 3.7;
#declare NS = 1;
#declare NLT = 129;
#declare LINES = array[129] { 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164 };
#declare LR = 820.4092442895686;  // line rate, Hz
#declare TAU = 0.0009481228746086409;  // exposure, s
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
// film: 504 x 4 samples spanning y/z in [0.2399609798, 0.3120123485] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 482.6323265, 1748.752346>
  right <0, 126, 0>
  up <1, 0, 0>
  aperture 142.84521 blur_samples 19 focal_point <0, 2751.866356, 9971.0121> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 57130.498
  pigment { function { max(0.002, min(0.98, 0.723956 * (1 + 0.058172 * ((y / 57130.498) - 0.2759866642) / 0.03602568433 + 0.0573538 * sin(21.795353 * ((y / 57130.498) - 0.2759866642) / 0.03602568433 + 1.45107)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 3301.500904, 12611.78159> + 378353 * <-0.5066169996, -0.6940411565, -0.5115135276> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, 3301.500904, 12611.78159>;  // mm
#declare V_0 = <-1509.712589, -126.3842087, -408.1044051>;  // mm/s
#declare TC_0 = 0.12189038665281589;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.1783563796, 0.1783563796, 0.1783563796> }
  finish { ambient 1 diffuse 0 } }
  no_shadow
  rotate <30.20527616, 171.9679717, 225.2537769>
  transform { Axis_Rotate_Trans(<0.1906817544, 0.7260956838, 0.6606251029>, 0 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
