// validation scene pv0139 (seed 139)
#version 3.7;
#declare NS = 2;
#declare NLT = 63;
#declare LINES = array[63] { 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79 };
#declare LR = 291.6228262934491;  // line rate, Hz
#declare TAU = 0.0008864588428542772;  // exposure, s
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
// film: 3056 x 4 samples spanning y/z in [0.1455996515, 0.3583823316] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 226.194535, 897.6294495>
  right <0, 191, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 12461.653
  pigment { function { max(0.002, min(0.98, 0.0205005 * (1 + 0.0111647 * ((y / 12461.653) - 0.2519909915) / 0.1063913401 + 0.00501014 * sin(7.7337613 * ((y / 12461.653) - 0.2519909915) / 0.1063913401 + 5.41269)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 815.9363477, 2655.662249> + 79669.9 * <-0.5440800555, -0.8041357343, -0.239463179> color rgb FL }
light_source { <0, 815.9363477, 2655.662249> + 79669.9 * <0.463960853, 0.2668234879, -0.844716256> color rgb FL * 0.5267 }


// ball 0: plain
#declare C0_0 = <0, 815.9363477, 2655.662249>;  // mm
#declare V_0 = <-917.1624693, 81.94970768, 74.46374672>;  // mm/s
#declare TC_0 = 0.16459616899707089;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.2501121478, 0.71107636, 0.4510740862> }
  finish { ambient 0.4851 diffuse 0.5149 phong 0.3748 phong_size 40 } }
  no_shadow
  rotate <58.77042198, 271.9181022, 257.5180216>
  transform { Axis_Rotate_Trans(<0.4403740645, 0.7323917978, -0.5193004312>, 480.20597 * (T - TC_0)) }
  scale 91.97128292
  translate P_0 }
#end
