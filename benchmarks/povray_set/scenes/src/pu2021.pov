// validation scene pu2021 (seed 2021)
#version 3.7;
#declare NS = 1;
#declare NLT = 149;
#declare LINES = array[149] { 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191 };
#declare LR = 15460.105095287243;  // line rate, Hz
#declare TAU = 3.303838215667862e-06;  // exposure, s
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
// film: 2432 x 4 samples spanning y/z in [-0.03804409314, 0.03632765599] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -1.7540158, 2043.786811>
  right <0, 152, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 20434.285
  pigment { function { max(0.002, min(0.98, 0.568949 * (1 + -0.181299 * ((y / 20434.285) - -0.0008582185729) / 0.03718587456 + 0 * sin(20.013989 * ((y / 20434.285) - -0.0008582185729) / 0.03718587456 + 0.280531)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -109.1691915, 7019.594027> + 210588 * <0.328064396, 0.6608260701, -0.6750427077> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, -109.1691915, 7019.594027>;  // mm
#declare V_0 = <-19064.97624, 14072.93745, 10661.74163>;  // mm/s
#declare TC_0 = 0.007567865760218248;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.09514678713, 0.06887204117, 0.06471101072> }
  finish { ambient 1 diffuse 0 } }
  no_shadow
  rotate <286.8800345, 194.7634244, 263.1711762>
  transform { Axis_Rotate_Trans(<-0.9020455211, 0.3972431486, -0.1688542529>, 12296.646 * (T - TC_0)) }
  scale 87.71374797
  translate P_0 }
#end
