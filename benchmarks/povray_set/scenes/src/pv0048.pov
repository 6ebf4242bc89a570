// validation scene pv0048 (seed 48)
#version 3.7;
#declare NS = 1;
#declare NLT = 157;
#declare LINES = array[157] { 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201 };
#declare LR = 492.10388646331745;  // line rate, Hz
#declare TAU = 9.265290190662902e-05;  // exposure, s
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
// film: 2784 x 4 samples spanning y/z in [-0.024957596, 0.033406437] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 12.59260196, 2980.906365>
  right <0, 173.9777175, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 47347.288
  pigment { function { max(0.002, min(0.98, 0.04373 * (1 + 0.183311 * ((y / 47347.288) - 0.004224420501) / 0.0291820165 + 0.224075 * sin(15.509765 * ((y / 47347.288) - 0.004224420501) / 0.0291820165 + 2.68542)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -131.1430755, 8879.59024> + 266388 * <0.2272584812, 0.4526520459, -0.8622410963> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, -131.1430755, 8879.59024>;  // mm
#declare V_0 = <689.4545641, 34.27252482, 45.11540772>;  // mm/s
#declare TC_0 = 0.17475984719013316;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.7977565356, 0.6598000854, 0.5908379842> }
  finish { ambient 0.1593 diffuse 0.8407 } }
  no_shadow
  rotate <325.3352282, 85.05405654, 84.70229932>
  transform { Axis_Rotate_Trans(<-0.1366512884, 0.9767909391, 0.1649420706>, 0 * (T - TC_0)) }
  scale 53.67873175
  translate P_0 }
#end
// ball 1: plain
#declare C0_1 = <0, 166.4393202, 7787.836753>;  // mm
#declare V_1 = <753.6205419, -91.74262034, 7.593427512>;  // mm/s
#declare TC_1 = 0.33241920672903075;  // s
#declare P_1 = C0_1 + V_1 * (T - TC_1);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.7977565356, 0.6598000854, 0.5908379842> }
  finish { ambient 0.1593 diffuse 0.8407 } }
  no_shadow
  rotate <358.7877754, 133.4218771, 247.9293327>
  transform { Axis_Rotate_Trans(<-0.1366512884, 0.9767909391, 0.1649420706>, 0 * (T - TC_1)) }
  scale 53.67873175
  translate P_1 }
#end
