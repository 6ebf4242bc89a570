// validation scene pv4234 (seed 4234)
#version 3.7;
#declare NS = 2;
#declare NLT = 105;
#declare LINES = array[105] { 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134 };
#declare LR = 348.1371304218282;  // line rate, Hz
#declare TAU = 0.001954417402514689;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.094974 * sin(753.9822369 * T + 2.6833));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 1504 x 4 samples spanning y/z in [-0.03338025376, 0.02771321811] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -4.359724005, 1538.62593>
  right <0, 94, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 5424.3268
  pigment { function { max(0.002, min(0.98, 0.56322 * (1 + 0.349232 * ((y / 5424.3268) - -0.002833517828) / 0.03054673593 + 0 * sin(24.713135 * ((y / 5424.3268) - -0.002833517828) / 0.03054673593 + 2.83548)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -29.0651109, 955.1260047> + 28653.8 * <0.909257025, 0.3513098642, 0.2232331557> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, -29.0651109, 955.1260047>;  // mm
#declare V_0 = <135.4597796, -4.199817413, -6.741218598>;  // mm/s
#declare TC_0 = 0.23553936892810845;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.03594391615, 0.1038329356, 0.03689716047> }
  finish { ambient 0.169 diffuse 0.831 } }
  no_shadow
  rotate <103.6640968, 23.15870718, 264.993221>
  transform { Axis_Rotate_Trans(<-0.7241918168, 0.579337107, -0.3740517731>, 57.261248 * (T - TC_0)) }
  scale 19.31807974
  translate P_0 }
#end
