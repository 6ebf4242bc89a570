// validation scene pu2027 (seed 2027)
#version 3.7;
#declare NS = 1;
#declare NLT = 177;
#declare LINES = array[177] { 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214, 215, 216, 217, 218, 219, 220, 221, 222, 223, 224, 225, 226 };
#declare LR = 1029.845090696449;  // line rate, Hz
#declare TAU = 6.175905552797382e-05;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.243614 * sin(628.3185307 * T + 0.592015));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 644 x 4 samples spanning y/z in [-0.0732862537, 0.07957606754] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 3.317341329, 1054.829734>
  right <0, 161.2437216, 0>
  up <1, 0, 0>
  aperture 51.960672 blur_samples 19 focal_point <0, 4.914127355, 1562.5669> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 10699.223
  pigment { function { max(0.002, min(0.98, 0.0105832 * (1 + -0.149943 * ((y / 10699.223) - 0.003144906919) / 0.07643116062 + 0.19956 * sin(6.9492677 * ((y / 10699.223) - 0.003144906919) / 0.07643116062 + 1.63185)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 104.34062, 1867.515483> + 56025.5 * <-0.2653148591, 0.4175853505, -0.8690399879> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, 104.34062, 1867.515483>;  // mm
#declare V_0 = <-249.8942508, 12.47256771, 97.96743315>;  // mm/s
#declare TC_0 = 0.13400073588414674;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.7788520494, 0.7788520494, 0.7788520494> }
  finish { ambient 1 diffuse 0 } }
  no_shadow
  rotate <143.9316746, 116.0411828, 255.7338287>
  transform { Axis_Rotate_Trans(<0.4368458643, -0.861999648, 0.257142563>, 0 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
