// validation scene pv0157 (seed 157)
#version 3.7;
#declare NS = 1;
#declare NLT = 194;
#declare LINES = array[194] { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193 };
#declare LR = 59580.458309186026;  // line rate, Hz
#declare TAU = 1.3664397859232667e-06;  // exposure, s
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
// film: 588 x 4 samples spanning y/z in [-0.02940042143, 0.03498282168] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 6.373197905, 2283.318149>
  right <0, 147.0074275, 0>
  up <1, 0, 0>
  aperture 10.335251 blur_samples 19 focal_point <0, 12.97284027, 4647.7643> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 29648.188
  pigment { function { max(0.002, min(0.98, 0.0310636 * (1 + 0.0589049 * ((y / 29648.188) - 0.002791200126) / 0.03219162155 + 0.0254573 * sin(17.418381 * ((y / 29648.188) - 0.002791200126) / 0.03219162155 + 3.45965)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 159.6567091, 6825.481769> + 204764 * <-0.007787723947, 0.488710319, -0.8724113568> color rgb FL }
light_source { <0, 159.6567091, 6825.481769> + 204764 * <-0.662556498, -0.5053002208, 0.5528929135> color rgb FL * 0.55 }


// ball 0: pingpong
#declare C0_0 = <0, 159.6567091, 6825.481769>;  // mm
#declare V_0 = <-11968.06178, -2692.059585, -2228.69505>;  // mm/s
#declare TC_0 = 0.0014098582384863764;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.6807395497, 0.6807395497, 0.6807395497> }
  finish { ambient 0.2461 diffuse 0.7539 phong 0.4555 phong_size 40 } }
  no_shadow
  rotate <169.3026076, 28.86025076, 110.1343734>
  transform { Axis_Rotate_Trans(<0.2109862273, 0.9197161556, 0.3310694868>, 4027.7484 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
