// validation scene pv3594 (seed 3594)
#version 3.7;
#declare NS = 1;
#declare NLT = 98;
#declare LINES = array[98] { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97 };
#declare LR = 64315.976447356865;  // line rate, Hz
#declare TAU = 1.2563601330308655e-06;  // exposure, s
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
// film: 1600 x 4 samples spanning y/z in [-0.0490645491, 0.054127238] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 2.453980004, 969.437409>
  right <0, 100.0379787, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 7049.5034
  pigment { function { max(0.002, min(0.98, 0.825204 * (1 + -0.205037 * ((y / 7049.5034) - 0.002531344449) / 0.05159589355 + 0 * sin(4.1472267 * ((y / 7049.5034) - 0.002531344449) / 0.05159589355 + 1.64075)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 72.15725795, 3196.514671> + 95895.4 * <-0.3385336123, 0.5766405563, -0.7435594544> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, 72.15725795, 3196.514671>;  // mm
#declare V_0 = <-36237.50998, 15102.48292, -16387.09393>;  // mm/s
#declare TC_0 = 0.00041980238023906413;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.190254627, 0.1214917574, 0.1055263894> }
  finish { ambient 0.3732 diffuse 0.6268 phong 0.6197 phong_size 40 } }
  no_shadow
  rotate <138.9174628, 1.256808446, 356.4953026>
  transform { Axis_Rotate_Trans(<0.2802401673, -0.6788258663, -0.6787200394>, 11931.558 * (T - TC_0)) }
  scale 36.70873539
  translate P_0 }
#end
