// validation scene pu2017 (seed 2017)
#version 3.7;
#declare NS = 1;
#declare NLT = 81;
#declare LINES = array[81] { 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102 };
#declare LR = 161.19745315682565;  // line rate, Hz
#declare TAU = 0.0005687173837324773;  // exposure, s
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
// film: 2672 x 4 samples spanning y/z in [-0.03966420359, 0.03203562951] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -8.884064412, 2329.154655>
  right <0, 167, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 20994.563
  pigment { function { max(0.002, min(0.98, 0.285818 * (1 + -0.237752 * ((y / 20994.563) - -0.003814287039) / 0.03584991655 + 0 * sin(4.63673 * ((y / 20994.563) - -0.003814287039) / 0.03584991655 + 2.82334)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -54.06051352, 6122.002091> + 183660 * <0.2325945387, -0.4898632944, -0.8401986274> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, -54.06051352, 6122.002091>;  // mm
#declare V_0 = <172.0000212, 23.55539364, 3.04271644>;  // mm/s
#declare TC_0 = 0.38462146135572933;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.3312080792, 0.6654824551, 0.3136341843> }
  finish { ambient 1 diffuse 0 } }
  no_shadow
  rotate <328.6840133, 37.41125843, 214.2324214>
  transform { Axis_Rotate_Trans(<-0.6923030092, 0.5396508407, -0.4790548127>, 112.48437 * (T - TC_0)) }
  scale 39.97925919
  translate P_0 }
#end
