// validation scene pu2019 (seed 2019)
#version 3.7;
#declare NS = 2;
#declare NLT = 37;
#declare LINES = array[37] { 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45 };
#declare LR = 480.57983594136886;  // line rate, Hz
#declare TAU = 0.0009801152488881446;  // exposure, s
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
// film: 2528 x 4 samples spanning y/z in [-0.02732108489, 0.03064469822] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 4.529488657, 2725.641165>
  right <0, 157.9939246, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 31014.151
  pigment { function { max(0.002, min(0.98, 0.0561855 * (1 + 0.395275 * ((y / 31014.151) - 0.001661806666) / 0.02898289155 + 0.127967 * sin(9.9480952 * ((y / 31014.151) - 0.001661806666) / 0.02898289155 + 0.0464848)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -109.579292, 8379.320099> + 251380 * <0.3288734181, 0.3149450569, -0.8903099943> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, -109.579292, 8379.320099>;  // mm
#declare V_0 = <-1047.936263, 40.66546442, -27.69847804>;  // mm/s
#declare TC_0 = 0.05618213245903647;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.6103047224, 0.7410843058, 0.1307795834> }
  finish { ambient 1 diffuse 0 } }
  no_shadow
  rotate <123.2478954, 276.6544527, 34.77174994>
  transform { Axis_Rotate_Trans(<0.815935758, 0.2751541724, -0.5084673247>, 755.82912 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
