// validation scene pu2002 (seed 2002)
#version 3.7;
#declare NS = 1;
#declare NLT = 83;
#declare LINES = array[83] { 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105 };
#declare LR = 790.5154174629922;  // line rate, Hz
#declare TAU = 0.0001273064086079615;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.222569 * sin(753.9822369 * T + 4.39536));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 2304 x 4 samples spanning y/z in [-0.06351422705, 0.04275189279] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -14.06740049, 1355.088529>
  right <0, 144, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 34797.42
  pigment { function { max(0.002, min(0.98, 0.0197342 * (1 + 0.297253 * ((y / 34797.42) - -0.01038116713) / 0.05313305992 + 0.0971612 * sin(17.799727 * ((y / 34797.42) - -0.01038116713) / 0.05313305992 + 1.50251)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -96.64317191, 6255.536618> + 187666 * <0.110928365, -0.4421275511, -0.8900663607> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, -96.64317191, 6255.536618>;  // mm
#declare V_0 = <2253.263171, 264.4475987, -180.9830956>;  // mm/s
#declare TC_0 = 0.08095983783010297;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.6450982777, 0.6450982777, 0.6450982777> }
  finish { ambient 1 diffuse 0 } }
  no_shadow
  rotate <60.58705168, 169.5621464, 80.91352768>
  transform { Axis_Rotate_Trans(<0.5804331724, -0.7867292031, 0.2101297059>, 0 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
