// validation scene pv0211 (seed 211)
#version 3.7;
#declare NS = 1;
#declare NLT = 153;
#declare LINES = array[153] { 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196 };
#declare LR = 100042.61986770021;  // line rate, Hz
#declare TAU = 2.331035981145626e-06;  // exposure, s
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
// film: 3184 x 4 samples spanning y/z in [-0.1223126757, 0.09342656174] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -13.32241819, 922.4098608>
  right <0, 199, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 5193.6022
  pigment { function { max(0.002, min(0.98, 0.114779 * (1 + 0.00264301 * ((y / 5193.6022) - -0.01444305699) / 0.1078696187 + 0 * sin(21.515255 * ((y / 5193.6022) - -0.01444305699) / 0.1078696187 + 0.641578)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -252.834968, 2076.022658> + 62280.7 * <0.6045412149, 0.1433219903, -0.7835743274> color rgb FL }
light_source { <0, -252.834968, 2076.022658> + 62280.7 * <0.2068294345, 0.8293796374, -0.518990368> color rgb FL * 0.2759 }


// ball 0: pingpong
#declare C0_0 = <0, -252.834968, 2076.022658>;  // mm
#declare V_0 = <28451.07496, 4330.053392, 1938.28854>;  // mm/s
#declare TC_0 = 0.0011994887794691113;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.7569120237, 0.7569120237, 0.7569120237> }
  finish { ambient 0.228 diffuse 0.772 phong 0.6651 phong_size 40 } }
  no_shadow
  rotate <101.0774919, 261.2343701, 313.9689123>
  transform { Axis_Rotate_Trans(<0.4926811853, 0.4380219494, -0.7519321921>, 11385.206 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
