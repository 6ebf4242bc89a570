// validation scene pv0054 (seed 54)
#version 3.7;
#declare NS = 1;
#declare NLT = 47;
#declare LINES = array[47] { 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59 };
#declare LR = 5166.673524590998;  // line rate, Hz
#declare TAU = 7.887309784332432e-06;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.32676 * sin(753.9822369 * T + 3.12545));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 2784 x 4 samples spanning y/z in [-0.03481132693, 0.04476198715] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 10.8793689, 2186.662727>
  right <0, 174, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 6320.1558
  pigment { function { max(0.002, min(0.98, 0.0584886 * (1 + -0.133489 * ((y / 6320.1558) - 0.004975330108) / 0.03978665704 + 0 * sin(20.65518 * ((y / 6320.1558) - 0.004975330108) / 0.03978665704 + 1.46583)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 97.91945628, 2705.435265> + 81163.1 * <0.1966973019, 0.690087285, -0.6964838193> color rgb FL }


// ball 0: pingpong
#declare C0_0 = <0, 97.91945628, 2705.435265>;  // mm
#declare V_0 = <-4863.427491, 424.6360251, 158.4816483>;  // mm/s
#declare TC_0 = 0.006967732686932221;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.7849207574, 0.7849207574, 0.7849207574> }
  finish { ambient 0.1699 diffuse 0.8301 phong 0.3 phong_size 40 } }
  no_shadow
  rotate <123.2487662, 291.0521079, 154.658133>
  transform { Axis_Rotate_Trans(<-0.7289616662, -0.4044462118, -0.55230259>, 0 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
