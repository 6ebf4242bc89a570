// validation scene pv0100 (seed 100)
#version 3.7;
#declare NS = 1;
#declare NLT = 147;
#declare LINES = array[147] { 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187 };
#declare LR = 51299.57030559522;  // line rate, Hz
#declare TAU = 1.292234240062434e-06;  // exposure, s
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
// film: 2384 x 4 samples spanning y/z in [-0.046037157, 0.1029287562] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 28.45230864, 1000.228823>
  right <0, 149, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 1684.6063
  pigment { function { max(0.002, min(0.98, 0.0125627 * (1 + -0.058019 * ((y / 1684.6063) - 0.02844579959) / 0.07448295659 + 0.233313 * sin(8.5457476 * ((y / 1684.6063) - 0.02844579959) / 0.07448295659 + 0.516881)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 11.13241173, 650.5765691> + 19517.3 * <0.153234539, -0.5736963909, -0.8046065045> color rgb FL }


// ball 0: pingpong
#declare C0_0 = <0, 11.13241173, 650.5765691>;  // mm
#declare V_0 = <-14691.87273, -14931.73199, -281.6712478>;  // mm/s
#declare TC_0 = 0.002222240835954255;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.854145109, 0.384365299, 0.04270725545> }
  finish { ambient 0.1047 diffuse 0.8953 phong 0.2086 phong_size 40 } }
  no_shadow
  rotate <290.6929487, 115.8212056, 201.0696825>
  transform { Axis_Rotate_Trans(<-0.05593337269, -0.9969075157, -0.0551983965>, 11370.342 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
