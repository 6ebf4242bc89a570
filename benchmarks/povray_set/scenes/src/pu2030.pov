// validation scene pu2030 (seed 2030)
#version 3.7;
#declare NS = 1;
#declare NLT = 91;
#declare LINES = array[91] { 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116 };
#declare LR = 560.3090440770768;  // line rate, Hz
#declare TAU = 0.0002473506943560294;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.219988 * sin(753.9822369 * T + 5.41712));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 1872 x 4 samples spanning y/z in [-0.4705238304, -0.3209033596] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -344.2872932, 870.0416098>
  right <0, 130.1760352, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 5541.1751
  pigment { function { max(0.002, min(0.98, 0.0499198 * (1 + -0.200005 * ((y / 5541.1751) - -0.395713595) / 0.07481023538 + 0.0333023 * sin(5.2017169 * ((y / 5541.1751) - -0.395713595) / 0.07481023538 + 4.7667)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -703.3289857, 1837.756943> + 55132.7 * <0.8332794887, -0.5520805845, -0.02919455272> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, -703.3289857, 1837.756943>;  // mm
#declare V_0 = <-442.8961123, -77.33484608, -42.50754755>;  // mm/s
#declare TC_0 = 0.1267157843524531;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.6725446216, 0.8166613262, 0.1441167046> }
  finish { ambient 1 diffuse 0 } }
  no_shadow
  rotate <285.8911037, 176.6666351, 299.2647797>
  transform { Axis_Rotate_Trans(<-0.1685581925, 0.9661780626, -0.1951616946>, 392.01502 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
