// validation scene pv0095 (seed 95)
#version 3.7;
#declare NS = 1;
#declare NLT = 69;
#declare LINES = array[69] { 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86 };
#declare LR = 923.1541515897641;  // line rate, Hz
#declare TAU = 0.0002200498275235765;  // exposure, s
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
// film: 2736 x 4 samples spanning y/z in [0.03795143661, 0.231209465] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 119.0804712, 884.8274064>
  right <0, 171, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 4782.4658
  pigment { function { max(0.002, min(0.98, 0.491752 * (1 + 0.266895 * ((y / 4782.4658) - 0.1345804508) / 0.09662901418 + 0 * sin(3.921701 * ((y / 4782.4658) - 0.1345804508) / 0.09662901418 + 4.62458)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 300.5768595, 1895.662591> + 56869.9 * <-0.9669688895, -0.1412466831, 0.2121804449> color rgb FL }


// ball 0: golf
#declare C0_0 = <0, 300.5768595, 1895.662591>;  // mm
#declare V_0 = <641.0542854, 744.2536672, 300.5304043>;  // mm/s
#declare TC_0 = 0.05632862064309713;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.1046198988, 0.1046198988, 0.1046198988> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.5666 diffuse 0.4334 phong 0.35 phong_size 40 } }
  no_shadow
  rotate <47.87846925, 39.52097554, 185.4754835>
  transform { Axis_Rotate_Trans(<0.76183256, 0.3905349813, 0.5168109702>, 629.15185 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
