// validation scene pv0118 (seed 118)
#version 3.7;
#declare NS = 1;
#declare NLT = 113;
#declare LINES = array[113] { 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144 };
#declare LR = 21794.66626408628;  // line rate, Hz
#declare TAU = 9.464105897912422e-06;  // exposure, s
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
// film: 3072 x 4 samples spanning y/z in [-0.01745011884, 0.01834855415] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 2.409301305, 5363.327296>
  right <0, 192, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 15189.923
  pigment { function { max(0.002, min(0.98, 0.749833 * (1 + 0.0392495 * ((y / 15189.923) - 0.0004492176538) / 0.01789933649 + 0.00612926 * sin(10.40017 * ((y / 15189.923) - 0.0004492176538) / 0.01789933649 + 5.04551)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -7.795752892, 3081.906862> + 92457.2 * <0.3214149599, -0.1377355234, -0.9368678397> color rgb FL }


// ball 0: golf
#declare C0_0 = <0, -7.795752892, 3081.906862>;  // mm
#declare V_0 = <-8590.688977, -589.2684758, -458.6784928>;  // mm/s
#declare TC_0 = 0.004037685135147414;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.1242601575, 0.1242601575, 0.1242601575> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.4016 diffuse 0.5984 phong 0.5977 phong_size 40 } }
  no_shadow
  rotate <355.4372337, 359.6154794, 11.9599114>
  transform { Axis_Rotate_Trans(<0.5795992067, 0.08898178257, -0.810029013>, 0 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
