// validation scene pv0132 (seed 132)
#version 3.7;
#declare NS = 1;
#declare NLT = 165;
#declare LINES = array[165] { 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211 };
#declare LR = 4629.006733512773;  // line rate, Hz
#declare TAU = 9.47847118329469e-06;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.23943 * sin(628.3185307 * T + 3.85373));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 1424 x 4 samples spanning y/z in [-0.04081534966, 0.05829646524] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 7.848808381, 897.9756862>
  right <0, 89, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 2095.396
  pigment { function { max(0.002, min(0.98, 0.667064 * (1 + -0.275976 * ((y / 2095.396) - 0.008740557792) / 0.04955590745 + 0.118373 * sin(3.9630232 * ((y / 2095.396) - 0.008740557792) / 0.04955590745 + 3.56987)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 23.16751336, 868.5485995> + 26056.5 * <-0.2575105656, -0.5158655105, -0.8170502333> color rgb FL }
light_source { <0, 23.16751336, 868.5485995> + 26056.5 * <-0.8693609638, -0.4700043275, -0.1526677655> color rgb FL * 0.6451 }


// ball 0: plain
#declare C0_0 = <0, 23.16751336, 868.5485995>;  // mm
#declare V_0 = <-1177.253796, 844.3047493, 88.21579939>;  // mm/s
#declare TC_0 = 0.027867749481994577;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.06396044483, 0.2087937184, 0.1389824423> }
  finish { ambient 0.5787 diffuse 0.4213 } }
  no_shadow
  rotate <263.462001, 233.3738165, 57.51554063>
  transform { Axis_Rotate_Trans(<0.3434176232, -0.6099888327, 0.7141274116>, 354.12906 * (T - TC_0)) }
  scale 19.86352544
  translate P_0 }
#end
