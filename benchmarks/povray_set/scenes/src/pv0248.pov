// validation scene pv0248 (seed 248)
#version 3.7;
#declare NS = 1;
#declare NLT = 95;
#declare LINES = array[95] { 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121 };
#declare LR = 472.2080559710131;  // line rate, Hz
#declare TAU = 9.477493292301229e-05;  // exposure, s
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
// film: 2928 x 4 samples spanning y/z in [0.2549444226, 0.3279059719] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 722.4386536, 2478.984866>
  right <0, 180.8705766, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 28936.996
  pigment { function { max(0.002, min(0.98, 0.120771 * (1 + -0.369219 * ((y / 28936.996) - 0.2914251973) / 0.03648077466 + 0.192511 * sin(12.439283 * ((y / 28936.996) - 0.2914251973) / 0.03648077466 + 1.95342)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 1667.757576, 5372.040863> + 161161 * <-0.4650260489, -0.7784571729, 0.4216102511> color rgb FL }
light_source { <0, 1667.757576, 5372.040863> + 161161 * <0.8649579442, -0.2826429289, -0.4146814795> color rgb FL * 0.3947 }


// ball 0: pingpong
#declare C0_0 = <0, 1667.757576, 5372.040863>;  // mm
#declare V_0 = <217.0583433, -8.07732324, -40.13646316>;  // mm/s
#declare TC_0 = 0.15671058353257436;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.8645694234, 0.3890562405, 0.04322847117> }
  finish { ambient 0.5453 diffuse 0.4547 phong 0.3 phong_size 40 } }
  no_shadow
  rotate <206.4810626, 306.2118356, 295.2874786>
  transform { Axis_Rotate_Trans(<-0.4375388367, -0.1758303521, 0.8818409458>, 127.54556 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
