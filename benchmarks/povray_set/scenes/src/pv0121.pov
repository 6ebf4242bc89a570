// validation scene pv0121 (seed 121)
#version 3.7;
#declare NS = 1;
#declare NLT = 41;
#declare LINES = array[41] { 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50 };
#declare LR = 2120.452936331973;  // line rate, Hz
#declare TAU = 1.9177025822404666e-05;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.157116 * sin(628.3185307 * T + 1.35089));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 2080 x 4 samples spanning y/z in [-0.0496139097, 0.03495740701] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -11.26789987, 1537.597354>
  right <0, 130.0366328, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 24973.586
  pigment { function { max(0.002, min(0.98, 0.541768 * (1 + 0.210078 * ((y / 24973.586) - -0.007328251343) / 0.04228565836 + 0 * sin(9.3859902 * ((y / 24973.586) - -0.007328251343) / 0.04228565836 + 5.51833)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -69.68731043, 6441.053347> + 193232 * <-0.09642055725, -0.5144919351, -0.8520569963> color rgb FL }


// ball 0: pingpong
#declare C0_0 = <0, -69.68731043, 6441.053347>;  // mm
#declare V_0 = <2523.770575, 81.36481475, -1262.092774>;  // mm/s
#declare TC_0 = 0.014147920704099641;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.1019828228, 0.04589227026, 0.00509914114> }
  finish { ambient 0.1954 diffuse 0.8046 phong 0.3 phong_size 40 } }
  no_shadow
  rotate <359.8260118, 189.2336089, 106.6686111>
  transform { Axis_Rotate_Trans(<0.93983207, -0.1021273941, 0.3260148395>, 96.973262 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
