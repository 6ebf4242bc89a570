// validation scene pv0089 (seed 89)
#version 3.7;
#declare NS = 2;
#declare NLT = 22;
#declare LINES = array[22] { 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33 };
#declare LR = 84.7397196524498;  // line rate, Hz
#declare TAU = 0.005703436129181255;  // exposure, s
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
// film: 1376 x 4 samples spanning y/z in [0.2533156343, 0.2695241133] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 1414.593223, 5411.192356>
  right <0, 87.70719793, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 34194.078
  pigment { function { max(0.002, min(0.98, 0.491282 * (1 + -0.253952 * ((y / 34194.078) - 0.2614198738) / 0.008104239525 + 0.135548 * sin(10.01927 * ((y / 34194.078) - 0.2614198738) / 0.008104239525 + 1.82468)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 3253.496508, 12236.51111> + 367095 * <-0.05803669665, -0.4567561834, -0.8876967561> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, 3253.496508, 12236.51111>;  // mm
#declare V_0 = <137.7696861, -2.731994181, -28.98028866>;  // mm/s
#declare TC_0 = 0.41302945234594196;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.09359961304, 0.152092837, 0.129266042> }
  finish { ambient 0.5756 diffuse 0.4244 phong 0.481 phong_size 40 } }
  no_shadow
  rotate <291.8454487, 323.249761, 76.06152374>
  transform { Axis_Rotate_Trans(<-0.3555967783, 0.8334626523, 0.4229550076>, 106.87639 * (T - TC_0)) }
  scale 33.45164016
  translate P_0 }
#end
