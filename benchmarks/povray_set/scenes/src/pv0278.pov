// validation scene pv0278 (seed 278)
#version 3.7;
#declare NS = 1;
#declare NLT = 111;
#declare LINES = array[111] { 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142 };
#declare LR = 53024.11431502055;  // line rate, Hz
#declare TAU = 8.657596337242e-07;  // exposure, s
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
// film: 2416 x 4 samples spanning y/z in [-0.1152232053, -0.09221360797] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -680.6498697, 6562.479042>
  right <0, 151, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 11816.886
  pigment { function { max(0.002, min(0.98, 0.235379 * (1 + 0.000337962 * ((y / 11816.886) - -0.1037184066) / 0.01150479865 + 0.231664 * sin(4.8615899 * ((y / 11816.886) - -0.1037184066) / 0.01150479865 + 3.08983)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -595.0616455, 5698.196157> + 170946 * <-0.521480687, -0.01743914662, -0.8530848547> color rgb FL }


// ball 0: golf
#declare C0_0 = <0, -595.0616455, 5698.196157>;  // mm
#declare V_0 = <-21405.38988, -32568.83556, 13759.01759>;  // mm/s
#declare TC_0 = 0.0016407629080445543;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.8961279184, 0.8961279184, 0.8961279184> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.4616 diffuse 0.5384 phong 0.35 phong_size 40 } }
  no_shadow
  rotate <107.4823359, 266.587444, 22.43089675>
  transform { Axis_Rotate_Trans(<0.5285055704, -0.5042835661, -0.6829201616>, 0 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
