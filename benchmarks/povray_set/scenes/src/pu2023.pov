// validation scene pu2023 (seed 2023)
#version 3.7;
#declare NS = 1;
#declare NLT = 97;
#declare LINES = array[97] { 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123 };
#declare LR = 3051.3675356939816;  // line rate, Hz
#declare TAU = 1.9478658773330678e-05;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.327974 * sin(628.3185307 * T + 3.44089));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 1296 x 4 samples spanning y/z in [-0.1946528785, -0.1807436082] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -1093.052141, 5823.454292>
  right <0, 81, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 47609.821
  pigment { function { max(0.002, min(0.98, 0.178866 * (1 + -0.300838 * ((y / 47609.821) - -0.1876982434) / 0.006954635165 + 0.0799358 * sin(19.637353 * ((y / 47609.821) - -0.1876982434) / 0.006954635165 + 2.34418)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -1916.877142, 10319.08467> + 309573 * <-0.4076109262, -0.3689090451, -0.8353199682> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, -1916.877142, 10319.08467>;  // mm
#declare V_0 = <1369.858092, -109.6053774, 42.84625993>;  // mm/s
#declare TC_0 = 0.024579143325958775;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.932983176, 0.4198424292, 0.0466491588> }
  finish { ambient 1 diffuse 0 } }
  no_shadow
  rotate <342.3342422, 258.3967488, 319.8067458>
  transform { Axis_Rotate_Trans(<0.5653194551, -0.2839081497, -0.7744740642>, 986.0737 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
