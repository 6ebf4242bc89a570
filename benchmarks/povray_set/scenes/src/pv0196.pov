// validation scene pv0196 (seed 196)
#version 3.7;
#declare NS = 1;
#declare NLT = 175;
#declare LINES = array[175] { 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214, 215, 216, 217, 218, 219, 220, 221, 222, 223, 224 };
#declare LR = 264.77402325468296;  // line rate, Hz
#declare TAU = 0.00037188242581715186;  // exposure, s
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
// film: 464 x 4 samples spanning y/z in [-0.04035245768, 0.04998412924] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 6.181692264, 1283.617745>
  right <0, 115.957646, 0>
  up <1, 0, 0>
  aperture 142.09551 blur_samples 19 focal_point <0, 32.20431764, 6687.1711> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 12013.557
  pigment { function { max(0.002, min(0.98, 0.0315858 * (1 + -0.114262 * ((y / 12013.557) - 0.004815835779) / 0.04516829346 + 0 * sin(7.3670072 * ((y / 12013.557) - 0.004815835779) / 0.04516829346 + 4.62182)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -120.1663537, 5434.824515> + 163045 * <-0.08611886359, 0.5126516262, -0.8542668503> color rgb FL }
light_source { <0, -120.1663537, 5434.824515> + 163045 * <-0.7784382356, -0.6276090933, 0.01186336567> color rgb FL * 0.3728 }


// ball 0: plain
#declare C0_0 = <0, -120.1663537, 5434.824515>;  // mm
#declare V_0 = <120.8083112, -1.199676261, -3.966992359>;  // mm/s
#declare TC_0 = 0.5174223600788108;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.5340957446, 0.493207764, 0.5387946234> }
  finish { ambient 0.2699 diffuse 0.7301 phong 0.5879 phong_size 40 } }
  no_shadow
  rotate <199.8455905, 263.8186681, 31.10945068>
  transform { Axis_Rotate_Trans(<-0.5333430545, -0.8436642504, -0.06144769074>, 0.16475874 * (T - TC_0)) }
  scale 36.66795099
  translate P_0 }
#end
