// validation scene pv0069 (seed 69)
#version 3.7;
#declare NS = 2;
#declare NLT = 87;
#declare LINES = array[87] { 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111 };
#declare LR = 4927.16404080986;  // line rate, Hz
#declare TAU = 5.309449840306315e-05;  // exposure, s
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
// film: 2080 x 4 samples spanning y/z in [-0.2539729622, -0.2403549552] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -2498.151027, 10107.26256>
  right <0, 137.6407724, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 22652.472
  pigment { function { max(0.002, min(0.98, 0.714395 * (1 + -0.312965 * ((y / 22652.472) - -0.2471639587) / 0.006809003503 + 0.185058 * sin(3.7865331 * ((y / 22652.472) - -0.2471639587) / 0.006809003503 + 5.35426)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -1270.677906, 5089.720483> + 152692 * <-0.4306132179, 0.4754815185, -0.7671307465> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, -1270.677906, 5089.720483>;  // mm
#declare V_0 = <-2291.004033, -147.9221259, 973.7650422>;  // mm/s
#declare TC_0 = 0.013801042432681638;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.2288729925, 0.2096752494, 0.1106990068> }
  finish { ambient 0.4181 diffuse 0.5819 } }
  no_shadow
  rotate <314.8866526, 95.52152218, 20.22001318>
  transform { Axis_Rotate_Trans(<-0.8054990818, -0.4727574784, -0.357311623>, 647.10065 * (T - TC_0)) }
  scale 19.19012731
  translate P_0 }
#end
