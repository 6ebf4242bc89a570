// validation scene pu2018 (seed 2018)
#version 3.7;
#declare NS = 1;
#declare NLT = 177;
#declare LINES = array[177] { 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214, 215, 216, 217, 218, 219, 220, 221, 222, 223, 224, 225, 226, 227 };
#declare LR = 23944.277553501834;  // line rate, Hz
#declare TAU = 2.0380565944993297e-05;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.26435 * sin(628.3185307 * T + 5.90977));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 1424 x 4 samples spanning y/z in [0.01435354456, 0.07025773652] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 67.35097809, 1592.009416>
  right <0, 89, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 9388.3133
  pigment { function { max(0.002, min(0.98, 0.145146 * (1 + 0.328545 * ((y / 9388.3133) - 0.04230564054) / 0.02795209598 + 0.135898 * sin(11.77103 * ((y / 9388.3133) - 0.04230564054) / 0.02795209598 + 4.53357)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 77.40533135, 1975.110838> + 59253.3 * <-0.9269762997, 0.3743624296, 0.02382668933> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, 77.40533135, 1975.110838>;  // mm
#declare V_0 = <9440.02137, -3205.946525, 173.4177681>;  // mm/s
#declare TC_0 = 0.005805144869767489;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.6000964382, 0.7286885321, 0.1285920939> }
  finish { ambient 1 diffuse 0 } }
  no_shadow
  rotate <76.68271396, 356.8442983, 345.9591725>
  transform { Axis_Rotate_Trans(<-0.9080349558, -0.3771538017, 0.1822841982>, 8516.9861 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
