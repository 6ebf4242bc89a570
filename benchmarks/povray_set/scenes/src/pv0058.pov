// validation scene pv0058 (seed 58)
#version 3.7;
#declare NS = 1;
#declare NLT = 91;
#declare LINES = array[91] { 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116 };
#declare LR = 34144.65639345575;  // line rate, Hz
#declare TAU = 1.8070174867355341e-06;  // exposure, s
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
// film: 2448 x 4 samples spanning y/z in [-0.07808278609, 0.08422143211] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 2.893371634, 942.6742058>
  right <0, 153, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 20567.76
  pigment { function { max(0.002, min(0.98, 0.294413 * (1 + -0.111414 * ((y / 20567.76) - 0.003069323013) / 0.0811521091 + 0.179642 * sin(3.485995 * ((y / 20567.76) - 0.003069323013) / 0.0811521091 + 3.84409)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -12.64342966, 5531.988431> + 165960 * <0.1059136356, 0.9915150071, 0.07536771511> color rgb FL }


// ball 0: pingpong
#declare C0_0 = <0, -12.64342966, 5531.988431>;  // mm
#declare V_0 = <17845.88773, 252.4588697, -1496.547784>;  // mm/s
#declare TC_0 = 0.0020793883289336027;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.7194040852, 0.3237318383, 0.03597020426> }
  finish { ambient 0.2294 diffuse 0.7706 phong 0.3 phong_size 40 } }
  no_shadow
  rotate <1.631787206, 128.2963802, 254.1711099>
  transform { Axis_Rotate_Trans(<0.4387731047, -0.8963559197, -0.06343680151>, 11023.641 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
