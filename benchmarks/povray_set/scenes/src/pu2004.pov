// validation scene pu2004 (seed 2004)
#version 3.7;
#declare NS = 1;
#declare NLT = 79;
#declare LINES = array[79] { 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100 };
#declare LR = 1135.0296467250553;  // line rate, Hz
#declare TAU = 4.736219665202613e-05;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.138686 * sin(753.9822369 * T + 4.80365));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 480 x 4 samples spanning y/z in [-0.01872026635, 0.0204638427] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 2.669821609, 3062.465957>
  right <0, 120, 0>
  up <1, 0, 0>
  aperture 10.505977 blur_samples 19 focal_point <0, 3.093527232, 3548.485> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 13852.377
  pigment { function { max(0.002, min(0.98, 0.22584 * (1 + 0.0693159 * ((y / 13852.377) - 0.0008717881756) / 0.01959205452 + 0 * sin(22.173 * ((y / 13852.377) - 0.0008717881756) / 0.01959205452 + 5.9126)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 43.78008209, 5094.294211> + 152829 * <-0.4781235166, -0.07823617636, -0.8748011223> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, 43.78008209, 5094.294211>;  // mm
#declare V_0 = <-1119.789589, -456.7020959, 357.8591679>;  // mm/s
#declare TC_0 = 0.05374308959770844;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.7513927638, 0.7346951468, 0.6846022959> }
  finish { ambient 1 diffuse 0 } }
  no_shadow
  rotate <74.30863078, 300.1825525, 264.1346154>
  transform { Axis_Rotate_Trans(<-0.504164589, 0.1562783077, 0.8493498441>, 896.87814 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
