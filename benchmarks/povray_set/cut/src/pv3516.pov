// validation scene pv3516 (seed 3516)
#version 3.7;
#declare NS = 1;
#declare NLT = 137;
#declare LINES = array[137] { 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176 };
#declare LR = 2393.045608684494;  // line rate, Hz
#declare TAU = 6.294938332650943e-05;  // exposure, s
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
// film: 2480 x 4 samples spanning y/z in [0.3155544295, 0.337053107] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 2154.977619, 6604.206965>
  right <0, 141.9817156, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 48074.317
  pigment { function { max(0.002, min(0.98, 0.0193446 * (1 + -0.0807278 * ((y / 48074.317) - 0.3263037682) / 0.01074933874 + 0.0956245 * sin(21.6972 * ((y / 48074.317) - 0.3263037682) / 0.01074933874 + 5.47858)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 3061.719753, 9117.802722> + 273534 * <0.3991070608, -0.6113314494, -0.683364773> color rgb FL }
light_source { <0, 3061.719753, 9117.802722> + 273534 * <0.971511791, -0.2150336881, -0.09962606508> color rgb FL * 0.429 }


// ball 0: golf
#declare C0_0 = <0, 3061.719753, 9117.802722>;  // mm
#declare V_0 = <789.3772275, 123.0325062, -369.0820957>;  // mm/s
#declare TC_0 = 0.04513077377550268;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.8765214026, 0.8765214026, 0.8765214026> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.4015 diffuse 0.5985 phong 0.3338 phong_size 40 } }
  no_shadow
  rotate <210.9709435, 15.27293219, 266.4474991>
  transform { Axis_Rotate_Trans(<0.7127532259, -0.6421663372, -0.2821439958>, 625.8674 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
