// validation scene pv0194 (seed 194)
#version 3.7;
#declare NS = 4;
#declare NLT = 43;
#declare LINES = array[43] { 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52 };
#declare LR = 86.71721987978833;  // line rate, Hz
#declare TAU = 0.004239064635107973;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.289944 * sin(753.9822369 * T + 5.82625));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 2000 x 4 samples spanning y/z in [-0.02005195327, 0.0394827928] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 20.39863359, 2099.61423>
  right <0, 125, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 8432.293
  pigment { function { max(0.002, min(0.98, 0.0669716 * (1 + -0.106096 * ((y / 8432.293) - 0.009715419765) / 0.02976737303 + 0 * sin(11.909008 * ((y / 8432.293) - 0.009715419765) / 0.02976737303 + 2.16809)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 24.18280788, 1601.627159> + 48048.8 * <0.4363120067, 0.468741558, -0.7680580607> color rgb FL }


// ball 0: golf
#declare C0_0 = <0, 24.18280788, 1601.627159>;  // mm
#declare V_0 = <100.1539298, 83.82909416, 46.83563252>;  // mm/s
#declare TC_0 = 0.35748378514640716;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.7227776162, 0.7227776162, 0.7227776162> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.3015 diffuse 0.6985 phong 0.35 phong_size 40 } }
  no_shadow
  rotate <52.41555287, 249.1885051, 159.8355732>
  transform { Axis_Rotate_Trans(<-0.9468194308, -0.3091517218, 0.08920862318>, 64.919138 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
