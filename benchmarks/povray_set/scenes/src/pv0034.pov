// validation scene pv0034 (seed 34)
#version 3.7;
#declare NS = 1;
#declare NLT = 131;
#declare LINES = array[131] { 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168 };
#declare LR = 33251.374442499386;  // line rate, Hz
#declare TAU = 1.7449892121753192e-06;  // exposure, s
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
// film: 1312 x 4 samples spanning y/z in [-0.2472027149, -0.2154625711] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -597.6430632, 2583.479164>
  right <0, 82, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 9284.0353
  pigment { function { max(0.002, min(0.98, 0.505627 * (1 + 0.0103885 * ((y / 9284.0353) - -0.231332643) / 0.01587007187 + 0 * sin(23.206167 * ((y / 9284.0353) - -0.231332643) / 0.01587007187 + 6.27465)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -684.5807623, 3023.565217> + 90707 * <0.1382657049, -0.297263781, -0.9447310937> color rgb FL }


// ball 0: golf
#declare C0_0 = <0, -684.5807623, 3023.565217>;  // mm
#declare V_0 = <-11436.92226, -1262.682761, -4786.810298>;  // mm/s
#declare TC_0 = 0.0030976163159244694;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.2612381499, 0.2612381499, 0.2612381499> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.3408 diffuse 0.6592 phong 0.35 phong_size 40 } }
  no_shadow
  rotate <98.87316594, 131.7232835, 127.6529777>
  transform { Axis_Rotate_Trans(<-0.2820483034, -0.9422794365, 0.1804389595>, 6384.0894 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
