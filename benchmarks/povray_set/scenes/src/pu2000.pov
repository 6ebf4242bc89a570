// validation scene pu2000 (seed 2000)
#version 3.7;
#declare NS = 1;
#declare NLT = 161;
#declare LINES = array[161] { 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214, 215, 216, 217, 218, 219, 220, 221, 222, 223, 224, 225, 226 };
#declare LR = 5652.501675848662;  // line rate, Hz
#declare TAU = 3.788870362993546e-05;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.169451 * sin(628.3185307 * T + 2.485));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 652 x 4 samples spanning y/z in [-0.05633066883, 0.109703809] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 26.19884122, 981.7238093>
  right <0, 163, 0>
  up <1, 0, 0>
  aperture 85.521214 blur_samples 19 focal_point <0, 293.4241221, 10995.198> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 35267.554
  pigment { function { max(0.002, min(0.98, 0.0970916 * (1 + -0.27403 * ((y / 35267.554) - 0.02668657006) / 0.08301723889 + 0.0265432 * sin(14.13908 * ((y / 35267.554) - 0.02668657006) / 0.08301723889 + 4.6308)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -150.7951447, 7056.198448> + 211686 * <-0.5516398424, -0.07889870792, -0.8303423861> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, -150.7951447, 7056.198448>;  // mm
#declare V_0 = <-15055.1307, 15440.31614, -1935.027737>;  // mm/s
#declare TC_0 = 0.01680671770623346;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.690094062, 0.690094062, 0.690094062> }
  finish { ambient 1 diffuse 0 } }
  no_shadow
  rotate <178.1649842, 12.26228832, 149.469614>
  transform { Axis_Rotate_Trans(<0.2376053735, 0.8509522463, 0.4684271139>, 11976.397 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
// ball 1: plain
#declare C0_1 = <0, 557.4181856, 8058.948252>;  // mm
#declare V_1 = <-19040.04831, -3827.477774, 70.53808637>;  // mm/s
#declare TC_1 = 0.0337275412283672;  // s
#declare P_1 = C0_1 + V_1 * (T - TC_1);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.690094062, 0.690094062, 0.690094062> }
  finish { ambient 1 diffuse 0 } }
  no_shadow
  rotate <297.2157234, 266.9945483, 242.6503096>
  transform { Axis_Rotate_Trans(<0.2376053735, 0.8509522463, 0.4684271139>, 11976.397 * (T - TC_1)) }
  scale 110
  translate P_1 }
#end
