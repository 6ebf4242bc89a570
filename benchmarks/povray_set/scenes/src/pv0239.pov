// validation scene pv0239 (seed 239)
#version 3.7;
#declare NS = 1;
#declare NLT = 101;
#declare LINES = array[101] { 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128 };
#declare LR = 2435.359286448891;  // line rate, Hz
#declare TAU = 0.0001030240164872765;  // exposure, s
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
// film: 2816 x 4 samples spanning y/z in [-0.09566067962, -0.04609767193] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -251.6944697, 3551.035504>
  right <0, 176, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 22810.606
  pigment { function { max(0.002, min(0.98, 0.159798 * (1 + -0.0894966 * ((y / 22810.606) - -0.07087917578) / 0.02478150384 + 0.118598 * sin(3.424076 * ((y / 22810.606) - -0.07087917578) / 0.02478150384 + 1.69892)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -406.7480308, 4679.512327> + 140385 * <-0.04502528785, 0.1139667407, -0.9924637552> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, -406.7480308, 4679.512327>;  // mm
#declare V_0 = <559.6858436, 11.55934195, -310.9856666>;  // mm/s
#declare TC_0 = 0.032028128430173185;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.6579202668, 0.6268991573, 0.6222062093> }
  finish { ambient 0.5756 diffuse 0.4244 } }
  no_shadow
  rotate <35.78565288, 95.72380017, 288.4625001>
  transform { Axis_Rotate_Trans(<-0.2797199284, 0.6514271401, 0.7052655123>, 576.11957 * (T - TC_0)) }
  scale 10.40077587
  translate P_0 }
#end
