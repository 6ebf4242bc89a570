// validation scene pv1001_a030 (seed 1001)
#version 3.7;
#declare NS = 1;
#declare NLT = 121;
#declare LINES = array[121] { 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155 };
#declare LR = 8825.12332768649;  // line rate, Hz
#declare TAU = 9.983947833692176e-06;  // exposure, s
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
// film: 2752 x 4 samples spanning y/z in [-0.2438842352, -0.208660344] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -1104.898761, 4883.049369>
  right <0, 172, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 9875.8842
  pigment { function { max(0.002, min(0.98, 0.0202198 * (1 + 0.114608 * ((y / 9875.8842) - -0.2262722896) / 0.01761194563 + 0 * sin(11.760829 * ((y / 9875.8842) - -0.2262722896) / 0.01761194563 + 5.12996)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -492.4982688, 2122.682258> + 63680.5 * <-0.7030168773, -0.4804437579, -0.5243482294> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, -492.4982688, 2122.682258>;  // mm
#declare V_0 = <1693.568913, -2574.935756, -404.0312272>;  // mm/s
#declare TC_0 = 0.010764722086314946;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.2449983643, 0.3295420429, 0.4301165717> }
  finish { ambient 0.1308 diffuse 0.8692 } }
  no_shadow
  rotate <95.48783634, 162.4750788, 278.8674512>
  transform { Axis_Rotate_Trans(<0.4047138043, 0.1743895961, 0.8976608521>, 45.717576 * (T - TC_0)) }
  scale 11.063873
  translate P_0 }
#end
