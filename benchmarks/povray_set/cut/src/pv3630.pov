// validation scene pv3630 (seed 3630)
#version 3.7;
#declare NS = 1;
#declare NLT = 121;
#declare LINES = array[121] { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120 };
#declare LR = 51674.232679607696;  // line rate, Hz
#declare TAU = 1.0988442581903796e-05;  // exposure, s
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
// film: 2528 x 4 samples spanning y/z in [-0.07075814048, 0.0919495988] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 10.28703723, 970.866382>
  right <0, 157.9674742, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 5971.6618
  pigment { function { max(0.002, min(0.98, 0.0922627 * (1 + 0.163164 * ((y / 5971.6618) - 0.01059572916) / 0.08135386964 + 0.237288 * sin(22.439139 * ((y / 5971.6618) - 0.01059572916) / 0.08135386964 + 4.20762)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 19.62958088, 1555.746701> + 46672.4 * <-0.4614520203, 0.8670125244, -0.1880194548> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, 19.62958088, 1555.746701>;  // mm
#declare V_0 = <30337.42436, -536.6458769, 14158.48671>;  // mm/s
#declare TC_0 = 0.00042574410608871803;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.6084942015, 0.6740270767, 0.216000337> }
  finish { ambient 0.1357 diffuse 0.8643 phong 0.3353 phong_size 40 } }
  no_shadow
  rotate <239.4038821, 54.4210502, 206.9869273>
  transform { Axis_Rotate_Trans(<-0.4130467575, -0.5295745031, -0.7409070264>, 0 * (T - TC_0)) }
  scale 55.60097474
  translate P_0 }
#end
