// validation scene pv1047_a090 (seed 1047)
#version 3.7;
#declare NS = 2;
#declare NLT = 33;
#declare LINES = array[33] { 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40 };
#declare LR = 418.63899776183166;  // line rate, Hz
#declare TAU = 0.0022759348337592095;  // exposure, s
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
// film: 2528 x 4 samples spanning y/z in [-0.0561827576, 0.07341023321] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 10.49824985, 1218.779824>
  right <0, 157.9453226, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 18988.42
  pigment { function { max(0.002, min(0.98, 0.11424 * (1 + 0.376069 * ((y / 18988.42) - 0.008613737807) / 0.0647964954 + 0 * sin(17.287877 * ((y / 18988.42) - 0.008613737807) / 0.0647964954 + 0.692722)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -163.5054867, 4873.941214> + 146218 * <-0.7301233728, 0.6832188816, 0.01148130498> color rgb FL }
light_source { <0, -163.5054867, 4873.941214> + 146218 * <0.5058152115, 0.2983172156, 0.8094181927> color rgb FL * 0.6941 }


// ball 0: golf
#declare C0_0 = <0, -163.5054867, 4873.941214>;  // mm
#declare V_0 = <684.4111058, 15.07253984, -4.7012922>;  // mm/s
#declare TC_0 = 0.05732862950731089;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.8781701586, 0.8781701586, 0.8781701586> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.387 diffuse 0.613 phong 0.35 phong_size 40 } }
  no_shadow
  rotate <105.101416, 44.58807431, 7.193942449>
  transform { Axis_Rotate_Trans(<0.2138532094, 0.9761535245, -0.0372974711>, 0 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
