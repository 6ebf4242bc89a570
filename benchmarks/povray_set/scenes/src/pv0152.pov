// validation scene pv0152 (seed 152)
#version 3.7;
#declare NS = 3;
#declare NLT = 97;
#declare LINES = array[97] { 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122 };
#declare LR = 48.161693407206684;  // line rate, Hz
#declare TAU = 0.01932378677301162;  // exposure, s
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
// film: 2704 x 4 samples spanning y/z in [0.0755312592, 0.1408990403] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 279.7763668, 2585.371525>
  right <0, 169, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 29557.637
  pigment { function { max(0.002, min(0.98, 0.165465 * (1 + 0.383965 * ((y / 29557.637) - 0.1082151498) / 0.03268389057 + 0 * sin(19.567717 * ((y / 29557.637) - 0.1082151498) / 0.03268389057 + 5.34208)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 553.4608536, 5509.781785> + 165293 * <0.6788189033, 0.7285499277, -0.0917600099> color rgb FL }
light_source { <0, 553.4608536, 5509.781785> + 165293 * <0.5841960001, -0.8112543627, -0.02411208104> color rgb FL * 0.5709 }


// ball 0: plain
#declare C0_0 = <0, 553.4608536, 5509.781785>;  // mm
#declare V_0 = <-71.62561391, 5.543008651, 5.441307466>;  // mm/s
#declare TC_0 = 1.5364908242393112;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.6686851263, 0.6094487218, 0.6914854943> }
  finish { ambient 0.5434 diffuse 0.4566 } }
  no_shadow
  rotate <26.23599946, 12.24681297, 42.1322688>
  transform { Axis_Rotate_Trans(<-0.9009884211, 0.06083837449, 0.4295562328>, 47.844468 * (T - TC_0)) }
  scale 67.02394966
  translate P_0 }
#end
