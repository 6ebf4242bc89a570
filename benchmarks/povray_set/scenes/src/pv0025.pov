// validation scene pv0025 (seed 25)
#version 3.7;
#declare NS = 1;
#declare NLT = 107;
#declare LINES = array[107] { 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136 };
#declare LR = 59921.366230857755;  // line rate, Hz
#declare TAU = 7.841061252276681e-06;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.060808 * sin(753.9822369 * T + 0.917634));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 2528 x 4 samples spanning y/z in [-0.01171988057, 0.01724533925] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 15.0693582, 5454.518465>
  right <0, 157.9913263, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 28864.717
  pigment { function { max(0.002, min(0.98, 0.740591 * (1 + -0.193914 * ((y / 28864.717) - 0.00276272934) / 0.01448260991 + 0.122159 * sin(3.315289 * ((y / 28864.717) - 0.00276272934) / 0.01448260991 + 4.75636)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 24.61167575, 5622.503192> + 168675 * <-0.4417631371, -0.3730161666, -0.815907023> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, 24.61167575, 5622.503192>;  // mm
#declare V_0 = <22959.96642, 18611.8431, 7104.774377>;  // mm/s
#declare TC_0 = 0.001385148657662906;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.1238464779, 0.1745850007, 0.1574731709> }
  finish { ambient 0.5292 diffuse 0.4708 } }
  no_shadow
  rotate <134.2181898, 36.33864416, 305.5407031>
  transform { Axis_Rotate_Trans(<0.6410271978, -0.4212593589, 0.6415798347>, 6646.4697 * (T - TC_0)) }
  scale 19.23460219
  translate P_0 }
#end
