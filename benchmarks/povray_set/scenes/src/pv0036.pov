// validation scene pv0036 (seed 36)
#version 3.7;
#declare NS = 1;
#declare NLT = 157;
#declare LINES = array[157] { 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201 };
#declare LR = 210.70786582929068;  // line rate, Hz
#declare TAU = 0.00037966447133966694;  // exposure, s
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
// film: 2256 x 4 samples spanning y/z in [-0.01733835019, 0.04129990573] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 28.81803898, 2405.356274>
  right <0, 141.0458968, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 4079.0519
  pigment { function { max(0.002, min(0.98, 0.0382845 * (1 + 0.263503 * ((y / 4079.0519) - 0.01198077777) / 0.02931912796 + 0.182336 * sin(5.6997554 * ((y / 4079.0519) - 0.01198077777) / 0.02931912796 + 3.19679)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 37.26387903, 1814.915302> + 54447.5 * <0.2063455923, -0.9380635308, -0.2783133282> color rgb FL }


// ball 0: pingpong
#declare C0_0 = <0, 37.26387903, 1814.915302>;  // mm
#declare V_0 = <-56.02279477, -66.79924498, -7.912062744>;  // mm/s
#declare TC_0 = 0.5837465987133627;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.9226383041, 0.4151872368, 0.0461319152> }
  finish { ambient 0.1765 diffuse 0.8235 phong 0.5822 phong_size 40 } }
  no_shadow
  rotate <290.1925859, 244.3033169, 106.3067439>
  transform { Axis_Rotate_Trans(<-0.328489706, -0.6332850916, 0.7007456784>, 44.142051 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
