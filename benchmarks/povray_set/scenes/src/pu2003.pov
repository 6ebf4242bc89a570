// validation scene pu2003 (seed 2003)
#version 3.7;
#declare NS = 1;
#declare NLT = 79;
#declare LINES = array[79] { 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100 };
#declare LR = 2776.990013521402;  // line rate, Hz
#declare TAU = 0.00011560484705762454;  // exposure, s
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
// film: 2160 x 4 samples spanning y/z in [-0.03299561864, 0.04699159103] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 11.81099004, 1687.769839>
  right <0, 135, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 28035.917
  pigment { function { max(0.002, min(0.98, 0.0157161 * (1 + 0.0252146 * ((y / 28035.917) - 0.006997986195) / 0.03999360483 + 0 * sin(10.741007 * ((y / 28035.917) - 0.006997986195) / 0.03999360483 + 5.45827)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -25.02954426, 6494.324394> + 194830 * <-0.1168242142, 0.2845598856, -0.9515134127> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, -25.02954426, 6494.324394>;  // mm
#declare V_0 = <-4917.89692, 304.757934, -206.000687>;  // mm/s
#declare TC_0 = 0.021966229515765552;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.305339224, 0.6729549957, 0.1947778932> }
  finish { ambient 1 diffuse 0 } }
  no_shadow
  rotate <221.887618, 146.0481176, 201.9253111>
  transform { Axis_Rotate_Trans(<0.4062860017, 0.6756621096, -0.6151523377>, 3650.3206 * (T - TC_0)) }
  scale 64.77155226
  translate P_0 }
#end
