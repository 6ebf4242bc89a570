// validation scene pv0191 (seed 191)
#version 3.7;
#declare NS = 1;
#declare NLT = 139;
#declare LINES = array[139] { 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177 };
#declare LR = 90518.74658405242;  // line rate, Hz
#declare TAU = 2.163926208882414e-06;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.0882704 * sin(753.9822369 * T + 5.92194));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 3104 x 4 samples spanning y/z in [0.2594916296, 0.4171766798] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 416.2526879, 1230.300524>
  right <0, 194, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 11282.122
  pigment { function { max(0.002, min(0.98, 0.0103324 * (1 + 0.149842 * ((y / 11282.122) - 0.3383341547) / 0.07884252512 + 0.124054 * sin(7.2271783 * ((y / 11282.122) - 0.3383341547) / 0.07884252512 + 4.86534)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 847.9998484, 2598.49803> + 77954.9 * <-0.7603995781, 0.6201896563, 0.192762216> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, 847.9998484, 2598.49803>;  // mm
#declare V_0 = <26356.00343, 5542.938248, -12675.81975>;  // mm/s
#declare TC_0 = 0.001193123016785425;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.7518284197, 0.467997948, 0.3960437518> }
  finish { ambient 0.3903 diffuse 0.6097 } }
  no_shadow
  rotate <1.724126144, 55.17046487, 25.42641142>
  transform { Axis_Rotate_Trans(<0.3212896835, -0.7097486939, 0.626920833>, 0 * (T - TC_0)) }
  scale 18.4257076
  translate P_0 }
#end
