// validation scene pv0236 (seed 236)
#version 3.7;
#declare NS = 1;
#declare NLT = 139;
#declare LINES = array[139] { 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178 };
#declare LR = 20389.826703003095;  // line rate, Hz
#declare TAU = 3.7809054068686184e-05;  // exposure, s
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
// film: 2400 x 4 samples spanning y/z in [-0.06514246262, 0.06047691779] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -2.785524504, 1194.083266>
  right <0, 150, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 70086.412
  pigment { function { max(0.002, min(0.98, 0.624559 * (1 + -0.0395833 * ((y / 70086.412) - -0.002332772415) / 0.06280969021 + 0 * sin(6.7545698 * ((y / 70086.412) - -0.002332772415) / 0.06280969021 + 2.08498)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 811.2949579, 13717.29397> + 411519 * <-0.6372505358, -0.1042623439, -0.7635712922> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, 811.2949579, 13717.29397>;  // mm
#declare V_0 = <-25797.07553, 566.2921302, 1819.100579>;  // mm/s
#declare TC_0 = 0.005345803158981535;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.04450717999, 0.03847974708, 0.06436500208> }
  finish { ambient 0.3751 diffuse 0.6249 phong 0.6018 phong_size 40 } }
  no_shadow
  rotate <44.04955913, 43.95232356, 188.6110216>
  transform { Axis_Rotate_Trans(<-0.3124793795, 0.9434049951, 0.1111019923>, 8002.0624 * (T - TC_0)) }
  scale 79.5871632
  translate P_0 }
#end
