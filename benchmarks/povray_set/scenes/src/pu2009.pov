// validation scene pu2009 (seed 2009)
#version 3.7;
#declare NS = 1;
#declare NLT = 111;
#declare LINES = array[111] { 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141 };
#declare LR = 2602.4955704513;  // line rate, Hz
#declare TAU = 6.976799715708779e-05;  // exposure, s
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
// film: 608 x 4 samples spanning y/z in [-0.03606170405, 0.04390858933] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 7.457310156, 1900.705794>
  right <0, 152, 0>
  up <1, 0, 0>
  aperture 33.563212 blur_samples 19 focal_point <0, 20.06542324, 5114.239> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 30850.057
  pigment { function { max(0.002, min(0.98, 0.0163185 * (1 + 0.397369 * ((y / 30850.057) - 0.003923442638) / 0.03998514669 + 0.249084 * sin(8.7320017 * ((y / 30850.057) - 0.003923442638) / 0.03998514669 + 4.00506)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -282.2107708, 8122.615921> + 243678 * <0.1339775813, -0.5880848181, -0.7976253847> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, -282.2107708, 8122.615921>;  // mm
#declare V_0 = <1894.367065, -65.9676026, 163.9994733>;  // mm/s
#declare TC_0 = 0.03304520513942189;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.8633025463, 0.8441180453, 0.7865645422> }
  finish { ambient 1 diffuse 0 } }
  no_shadow
  rotate <3.542238204, 280.5495278, 118.8049798>
  transform { Axis_Rotate_Trans(<0.85404279, 0.1232841519, 0.5053829546>, 345.65053 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
