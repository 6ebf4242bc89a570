// validation scene pv0081 (seed 81)
#version 3.7;
#declare NS = 1;
#declare NLT = 29;
#declare LINES = array[29] { 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35 };
#declare LR = 53.96562910440632;  // line rate, Hz
#declare TAU = 0.0008224612469983607;  // exposure, s
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
// film: 1744 x 4 samples spanning y/z in [-0.05634693838, 0.06148053487] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 2.37449723, 925.0813668>
  right <0, 109, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 15463.513
  pigment { function { max(0.002, min(0.98, 0.0554373 * (1 + 0.0664746 * ((y / 15463.513) - 0.002566798246) / 0.05891373662 + 0.0612772 * sin(18.933304 * ((y / 15463.513) - 0.002566798246) / 0.05891373662 + 4.06874)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 42.62701455, 4551.330675> + 136540 * <0.4096108304, -0.3245198936, -0.8525877118> color rgb FL }
light_source { <0, 42.62701455, 4551.330675> + 136540 * <0.8774948658, -0.4498617825, -0.1662141303> color rgb FL * 0.3799 }


// ball 0: golf
#declare C0_0 = <0, 42.62701455, 4551.330675>;  // mm
#declare V_0 = <-102.6074983, -11.62423662, -9.123444042>;  // mm/s
#declare TC_0 = 0.3891365735655872;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.8192928404, 0.8192928404, 0.8192928404> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.4779 diffuse 0.5221 phong 0.35 phong_size 40 } }
  no_shadow
  rotate <45.74638998, 48.7489172, 241.8407307>
  transform { Axis_Rotate_Trans(<0.7673924284, -0.02640696098, 0.6406336966>, 0 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
