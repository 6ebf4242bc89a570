// validation scene pv0028 (seed 28)
#version 3.7;
#declare NS = 1;
#declare NLT = 143;
#declare LINES = array[143] { 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182 };
#declare LR = 222631.92338368052;  // line rate, Hz
#declare TAU = 7.20495202692234e-07;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.315355 * sin(753.9822369 * T + 3.92438));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 628 x 4 samples spanning y/z in [-0.2834694379, -0.2614196291] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -1939.871322, 7120.243145>
  right <0, 157, 0>
  up <1, 0, 0>
  aperture 18.163924 blur_samples 19 focal_point <0, -2537.175938, 9312.6329> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 72097.845
  pigment { function { max(0.002, min(0.98, 0.0120972 * (1 + 0.268719 * ((y / 72097.845) - -0.2724445335) / 0.0110249044 + 0 * sin(14.679571 * ((y / 72097.845) - -0.2724445335) / 0.0110249044 + 3.39113)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -3422.098547, 12823.42211> + 384703 * <-0.3231286036, 0.5075631629, -0.7987287031> color rgb FL }
light_source { <0, -3422.098547, 12823.42211> + 384703 * <0.6579504505, 0.7437315539, -0.1181718257> color rgb FL * 0.3401 }


// ball 0: plain
#declare C0_0 = <0, -3422.098547, 12823.42211>;  // mm
#declare V_0 = <-56814.40287, -17147.85177, 5068.553519>;  // mm/s
#declare TC_0 = 0.0004985807889226392;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.6150209974, 0.3065859242, 0.3894247346> }
  finish { ambient 0.2279 diffuse 0.7721 } }
  no_shadow
  rotate <234.812089, 320.7274328, 331.1529608>
  transform { Axis_Rotate_Trans(<-0.6549061438, -0.1487713781, -0.7409217367>, 13978.08 * (T - TC_0)) }
  scale 16.76775545
  translate P_0 }
#end
