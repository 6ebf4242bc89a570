// validation scene pv1083_a090 (seed 1083)
#version 3.7;
#declare NS = 1;
#declare NLT = 115;
#declare LINES = array[115] { 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146 };
#declare LR = 3064.4484210154737;  // line rate, Hz
#declare TAU = 6.287648560041227e-05;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.327119 * sin(753.9822369 * T + 3.9945));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 368 x 4 samples spanning y/z in [-0.1693309774, -0.06047139879] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -97.10591793, 845.125447>
  right <0, 92, 0>
  up <1, 0, 0>
  aperture 6.9035047 blur_samples 19 focal_point <0, -76.40119151, 664.92952> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 2045.66
  pigment { function { max(0.002, min(0.98, 0.206084 * (1 + 0.325838 * ((y / 2045.66) - -0.1149011881) / 0.05442978928 + 0 * sin(13.984353 * ((y / 2045.66) - -0.1149011881) / 0.05442978928 + 2.03586)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -48.07801199, 429.9393629> + 12898.2 * <0.5210773412, 0.8196376276, -0.2380600008> color rgb FL }
light_source { <0, -48.07801199, 429.9393629> + 12898.2 * <-0.9248669632, -0.2145822448, 0.3139674516> color rgb FL * 0.2203 }


// ball 0: plain
#declare C0_0 = <0, -48.07801199, 429.9393629>;  // mm
#declare V_0 = <1068.634869, -611.5240978, 53.73582578>;  // mm/s
#declare TC_0 = 0.029042746939270673;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.2590147153, 0.4248716448, 0.8254409843> }
  finish { ambient 0.2136 diffuse 0.7864 } }
  no_shadow
  rotate <213.1140066, 306.5879118, 297.6066265>
  transform { Axis_Rotate_Trans(<-0.452213271, -0.4827250855, 0.7499864327>, 1053.8676 * (T - TC_0)) }
  scale 18.99629282
  translate P_0 }
#end
