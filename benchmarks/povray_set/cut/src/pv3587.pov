// validation scene pv3587 (seed 3587)
#version 3.7;
#declare NS = 2;
#declare NLT = 155;
#declare LINES = array[155] { 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198 };
#declare LR = 471.8679007844871;  // line rate, Hz
#declare TAU = 0.0016145533137395256;  // exposure, s
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
// film: 2176 x 4 samples spanning y/z in [-0.1468201837, -0.1322374965] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -1324.027226, 9489.272786>
  right <0, 138.3790964, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 56401.946
  pigment { function { max(0.002, min(0.98, 0.0150213 * (1 + 0.176332 * ((y / 56401.946) - -0.1395288401) / 0.007291343582 + 0 * sin(18.403864 * ((y / 56401.946) - -0.1395288401) / 0.007291343582 + 1.13663)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -1931.962276, 13301.95247> + 399059 * <0.4653439366, 0.542872292, -0.6991027787> color rgb FL }
light_source { <0, -1931.962276, 13301.95247> + 399059 * <-0.1435342254, 0.9858995683, -0.08602306261> color rgb FL * 0.2918 }


// ball 0: golf
#declare C0_0 = <0, -1931.962276, 13301.95247>;  // mm
#declare V_0 = <-139.208754, -152.6519587, 102.0680829>;  // mm/s
#declare TC_0 = 0.2564276989361552;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.7545323409, 0.7545323409, 0.7545323409> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.343 diffuse 0.657 phong 0.35 phong_size 40 } }
  no_shadow
  rotate <103.7043306, 157.3664318, 196.0930398>
  transform { Axis_Rotate_Trans(<0.6032141001, 0.3843872225, -0.6988413358>, 133.32843 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
