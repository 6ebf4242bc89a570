// validation scene pv0009 (seed 9)
#version 3.7;
#declare NS = 1;
#declare NLT = 81;
#declare LINES = array[81] { 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101 };
#declare LR = 4585.485435632618;  // line rate, Hz
#declare TAU = 7.084967957678716e-05;  // exposure, s
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
// film: 2736 x 4 samples spanning y/z in [0.2446147402, 0.3266445989] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 595.4255469, 2084.606784>
  right <0, 171, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 6772.1439
  pigment { function { max(0.002, min(0.98, 0.019275 * (1 + 0.357558 * ((y / 6772.1439) - 0.2856296696) / 0.04101492937 + 0.0597818 * sin(10.345436 * ((y / 6772.1439) - 0.2856296696) / 0.04101492937 + 3.55279)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 512.1448502, 1909.066954> + 57272 * <-0.4535556384, 0.447188498, -0.7709148657> color rgb FL }


// ball 0: golf
#declare C0_0 = <0, 512.1448502, 1909.066954>;  // mm
#declare V_0 = <2638.941079, 842.0446146, 1276.737133>;  // mm/s
#declare TC_0 = 0.013302844563845917;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.7059654797, 0.7059654797, 0.7059654797> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.2895 diffuse 0.7105 phong 0.35 phong_size 40 } }
  no_shadow
  rotate <324.5495251, 4.919902676, 310.2684756>
  transform { Axis_Rotate_Trans(<0.7354681558, 0.65849427, -0.1595991482>, 629.4865 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
