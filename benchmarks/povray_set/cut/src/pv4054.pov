// validation scene pv4054 (seed 4054)
#version 3.7;
#declare NS = 1;
#declare NLT = 91;
#declare LINES = array[91] { 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123 };
#declare LR = 124119.67792529878;  // line rate, Hz
#declare TAU = 2.708596868307831e-06;  // exposure, s
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
// film: 1072 x 4 samples spanning y/z in [-0.004304826504, 0.005361960002] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 3.663458734, 6930.929236>
  right <0, 66.99981321, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 30368.758
  pigment { function { max(0.002, min(0.98, 0.141745 * (1 + -0.300227 * ((y / 30368.758) - 0.0005285667489) / 0.004833393253 + 0.0243887 * sin(20.875094 * ((y / 30368.758) - 0.0005285667489) / 0.004833393253 + 0.426173)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 19.50249928, 13626.46097> + 408794 * <-0.5043277213, -0.1856266911, -0.8433245408> color rgb FL }


// ball 0: golf
#declare C0_0 = <0, 19.50249928, 13626.46097>;  // mm
#declare V_0 = <48614.32366, -875.7999329, 2531.036189>;  // mm/s
#declare TC_0 = 0.0007412200993251856;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.782968835, 0.782968835, 0.782968835> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.462 diffuse 0.538 phong 0.6107 phong_size 40 } }
  no_shadow
  rotate <150.5171733, 320.0533826, 35.25851304>
  transform { Axis_Rotate_Trans(<-0.5428655939, 0.7674501012, 0.3410532058>, 5081.792 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
