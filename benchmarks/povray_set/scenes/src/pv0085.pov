// validation scene pv0085 (seed 85)
#version 3.7;
#declare NS = 1;
#declare NLT = 61;
#declare LINES = array[61] { 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76 };
#declare LR = 459.25265286478515;  // line rate, Hz
#declare TAU = 0.0002294461064026342;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.0895284 * sin(628.3185307 * T + 0.372096));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 2768 x 4 samples spanning y/z in [-0.007731644215, 0.01136674049] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 16.46400116, 9058.357692>
  right <0, 173, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 44134.83
  pigment { function { max(0.002, min(0.98, 0.0249118 * (1 + 0.0899291 * ((y / 44134.83) - 0.001817548138) / 0.009549192353 + 0 * sin(4.0707921 * ((y / 44134.83) - 0.001817548138) / 0.009549192353 + 1.05793)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 42.94324477, 11669.03515> + 350071 * <0.1572421181, 0.3946856361, -0.9052613794> color rgb FL }
light_source { <0, 42.94324477, 11669.03515> + 350071 * <0.1619206675, 0.4738919733, 0.8655680765> color rgb FL * 0.6194 }


// ball 0: golf
#declare C0_0 = <0, 42.94324477, 11669.03515>;  // mm
#declare V_0 = <352.855691, -24.89128532, -5.079312072>;  // mm/s
#declare TC_0 = 0.10016273115256993;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.7851865944, 0.7851865944, 0.7851865944> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.2686 diffuse 0.7314 phong 0.256 phong_size 40 } }
  no_shadow
  rotate <53.60022438, 218.451439, 203.6376159>
  transform { Axis_Rotate_Trans(<0.7806259392, -0.02689765414, 0.6244194578>, 0 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
