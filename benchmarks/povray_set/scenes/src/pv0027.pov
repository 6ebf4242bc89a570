// validation scene pv0027 (seed 27)
#version 3.7;
#declare NS = 1;
#declare NLT = 149;
#declare LINES = array[149] { 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190 };
#declare LR = 96.63590516791884;  // line rate, Hz
#declare TAU = 0.0008688621779061513;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.202667 * sin(628.3185307 * T + 4.1402));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 1328 x 4 samples spanning y/z in [-0.3789036015, -0.3593897771] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -1570.126625, 4253.394845>
  right <0, 83, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 39149.744
  pigment { function { max(0.002, min(0.98, 0.653143 * (1 + 0.348386 * ((y / 39149.744) - -0.3691466893) / 0.009756912187 + 0.152929 * sin(23.201241 * ((y / 39149.744) - -0.3691466893) / 0.009756912187 + 0.113655)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -4521.749052, 12176.3642> + 365291 * <-0.2694781349, 0.497824316, -0.8243497348> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, -4521.749052, 12176.3642>;  // mm
#declare V_0 = <-107.3446412, 5.402563401, -27.39913362>;  // mm/s
#declare TC_0 = 1.2003819884382856;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.04855087934, 0.06277610043, 0.0511522568> }
  finish { ambient 0.167 diffuse 0.833 phong 0.4621 phong_size 40 } }
  no_shadow
  rotate <241.7578642, 343.3502185, 90.74485228>
  transform { Axis_Rotate_Trans(<-0.9593490412, -0.1067869451, 0.261239288>, 0 * (T - TC_0)) }
  scale 78.52764335
  translate P_0 }
#end
