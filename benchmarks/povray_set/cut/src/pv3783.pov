// validation scene pv3783 (seed 3783)
#version 3.7;
#declare NS = 1;
#declare NLT = 59;
#declare LINES = array[59] { 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91 };
#declare LR = 31537.91011973848;  // line rate, Hz
#declare TAU = 5.71286155240156e-06;  // exposure, s
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
// film: 2416 x 4 samples spanning y/z in [-0.008187556605, 0.006648514797] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -7.832104154, 10177.89655>
  right <0, 151, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 26521.577
  pigment { function { max(0.002, min(0.98, 0.758724 * (1 + -0.106801 * ((y / 26521.577) - -0.0007695209036) / 0.007418035701 + 0.0277459 * sin(3.8968391 * ((y / 26521.577) - -0.0007695209036) / 0.007418035701 + 2.23891)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -15.34369634, 7251.372031> + 217541 * <-0.6792131887, 0.3273084488, 0.6569159943> color rgb FL }
light_source { <0, -15.34369634, 7251.372031> + 217541 * <0.7906233711, -0.5976370894, 0.1332088374> color rgb FL * 0.6671 }


// ball 0: golf
#declare C0_0 = <0, -15.34369634, 7251.372031>;  // mm
#declare V_0 = <-12252.15007, 610.8093397, -850.936129>;  // mm/s
#declare TC_0 = 0.002853708430847234;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.09009684641, 0.09009684641, 0.09009684641> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.4468 diffuse 0.5532 phong 0.35 phong_size 40 } }
  no_shadow
  rotate <334.4670511, 322.6230343, 5.313390966>
  transform { Axis_Rotate_Trans(<-0.04363357668, 0.4348008872, -0.8994688985>, 7041.1969 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
