// validation scene pv4080 (seed 4080)
#version 3.7;
#declare NS = 1;
#declare NLT = 181;
#declare LINES = array[181] { 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214, 215, 216, 217, 218, 219, 220, 221, 222, 223, 224, 225, 226, 227, 228, 229, 230, 231, 232 };
#declare LR = 116.60312194304741;  // line rate, Hz
#declare TAU = 0.004222270665178781;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.197906 * sin(753.9822369 * T + 1.28401));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 2704 x 4 samples spanning y/z in [-0.03266107785, 0.04413499537] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 12.62494278, 2200.633352>
  right <0, 169, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 44257.835
  pigment { function { max(0.002, min(0.98, 0.837615 * (1 + 0.111347 * ((y / 44257.835) - 0.005736958758) / 0.03839803661 + 0 * sin(21.984513 * ((y / 44257.835) - 0.005736958758) / 0.03839803661 + 0.882683)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -385.0349731, 13026.78265> + 390803 * <-0.062740923, 0.5270838623, -0.8474940582> color rgb FL }
light_source { <0, -385.0349731, 13026.78265> + 390803 * <0.9227308579, 0.3617952425, 0.1329359488> color rgb FL * 0.6993 }


// ball 0: plain
#declare C0_0 = <0, -385.0349731, 13026.78265>;  // mm
#declare V_0 = <-99.530541, 6.433463298, -45.1864715>;  // mm/s
#declare TC_0 = 1.2178061584779627;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.240081183, 0.2734658123, 0.2014154112> }
  finish { ambient 0.5488 diffuse 0.4512 phong 0.7303 phong_size 40 } }
  no_shadow
  rotate <8.416863665, 358.7913565, 337.5408525>
  transform { Axis_Rotate_Trans(<0.4603062974, 0.812348771, -0.3580608703>, 27.77573 * (T - TC_0)) }
  scale 72.11860798
  translate P_0 }
#end
