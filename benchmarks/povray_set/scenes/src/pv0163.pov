// validation scene pv0163 (seed 163)
#version 3.7;
#declare NS = 2;
#declare NLT = 37;
#declare LINES = array[37] { 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45 };
#declare LR = 47840.06297808217;  // line rate, Hz
#declare TAU = 5.656837034309933e-06;  // exposure, s
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
// film: 2528 x 4 samples spanning y/z in [-0.4481920582, -0.3036395758] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -406.4803164, 1081.306766>
  right <0, 156.3055773, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 5354.7665
  pigment { function { max(0.002, min(0.98, 0.600908 * (1 + -0.00661695 * ((y / 5354.7665) - -0.375915817) / 0.07227624119 + 0 * sin(15.280139 * ((y / 5354.7665) - -0.375915817) / 0.07227624119 + 2.88189)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -567.2504424, 1385.654665> + 41569.6 * <0.3245336289, 0.09547378147, -0.9410434> color rgb FL }


// ball 0: golf
#declare C0_0 = <0, -567.2504424, 1385.654665>;  // mm
#declare V_0 = <64380.21348, 5876.493437, -11496.41432>;  // mm/s
#declare TC_0 = 0.0005643805279347144;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.2021599029, 0.2021599029, 0.2021599029> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.2977 diffuse 0.7023 phong 0.35 phong_size 40 } }
  no_shadow
  rotate <55.27220667, 275.2729778, 200.2966853>
  transform { Axis_Rotate_Trans(<-0.3321939973, -0.8399362322, 0.4291320006>, 8586.834 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
