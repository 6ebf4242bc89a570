// validation scene pv0023 (seed 23)
#version 3.7;
#declare NS = 1;
#declare NLT = 119;
#declare LINES = array[119] { 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151 };
#declare LR = 4603.103343197365;  // line rate, Hz
#declare TAU = 1.6741456041174775e-05;  // exposure, s
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
// film: 2720 x 4 samples spanning y/z in [-0.08314161278, 0.0883292433] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 2.57156583, 991.422122>
  right <0, 170, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 1423.8208
  pigment { function { max(0.002, min(0.98, 0.148699 * (1 + 0.364857 * ((y / 1423.8208) - 0.002593815261) / 0.08573542804 + 0 * sin(22.036739 * ((y / 1423.8208) - 0.002593815261) / 0.08573542804 + 2.51639)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 18.37466945, 585.4207514> + 17562.6 * <-0.07104502004, 0.7244702625, -0.6856350661> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, 18.37466945, 585.4207514>;  // mm
#declare V_0 = <1121.886746, -390.7807557, 586.6363192>;  // mm/s
#declare TC_0 = 0.019986516300130645;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.4141594785, 0.3053134403, 0.4845012258> }
  finish { ambient 0.5398 diffuse 0.4602 phong 0.5532 phong_size 40 } }
  no_shadow
  rotate <327.4513367, 170.5829865, 182.0528792>
  transform { Axis_Rotate_Trans(<-0.178458693, 0.8909628959, 0.4175375589>, 0 * (T - TC_0)) }
  scale 13.63554887
  translate P_0 }
#end
