// validation scene pv3398 (seed 3398)
#version 3.7;
#declare NS = 1;
#declare NLT = 61;
#declare LINES = array[61] { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60 };
#declare LR = 624.5765959577345;  // line rate, Hz
#declare TAU = 0.00021235289027661126;  // exposure, s
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
// film: 2544 x 4 samples spanning y/z in [-0.3330867351, -0.3164408988] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -3102.123912, 9551.938209>
  right <0, 159, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 55256.451
  pigment { function { max(0.002, min(0.98, 0.685007 * (1 + -0.215879 * ((y / 55256.451) - -0.3247638169) / 0.008322918162 + 0.246929 * sin(15.911831 * ((y / 55256.451) - -0.3247638169) / 0.008322918162 + 4.68781)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -3149.516251, 9750.532015> + 292516 * <-0.1445854734, 0.5678049935, -0.8103656769> color rgb FL }


// ball 0: golf
#declare C0_0 = <0, -3149.516251, 9750.532015>;  // mm
#declare V_0 = <317.9596069, 4.290345112, 39.4548528>;  // mm/s
#declare TC_0 = 0.02401626973709892;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.2174908264, 0.2174908264, 0.2174908264> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.4558 diffuse 0.5442 phong 0.35 phong_size 40 } }
  no_shadow
  rotate <182.8793514, 344.5589493, 89.20819641>
  transform { Axis_Rotate_Trans(<0.6341511175, 0.7419026602, -0.217790732>, 126.08099 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
