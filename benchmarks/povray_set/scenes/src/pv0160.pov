// validation scene pv0160 (seed 160)
#version 3.7;
#declare NS = 1;
#declare NLT = 73;
#declare LINES = array[73] { 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91 };
#declare LR = 665.0112777505221;  // line rate, Hz
#declare TAU = 0.0003048534687507494;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.293059 * sin(628.3185307 * T + 2.66915));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 2832 x 4 samples spanning y/z in [0.1039059451, 0.1742522695] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 349.9401309, 2516.12293>
  right <0, 177, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 53765.182
  pigment { function { max(0.002, min(0.98, 0.794177 * (1 + 0.313103 * ((y / 53765.182) - 0.1390791073) / 0.03517316223 + 0.0495187 * sin(17.268168 * ((y / 53765.182) - 0.1390791073) / 0.03517316223 + 5.38844)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 1769.13761, 11219.56718> + 336587 * <-0.7056569749, -0.04964818469, -0.7068120624> color rgb FL }


// ball 0: pingpong
#declare C0_0 = <0, 1769.13761, 11219.56718>;  // mm
#declare V_0 = <-435.1486766, -274.7692525, 94.22034406>;  // mm/s
#declare TC_0 = 0.08270536431508935;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.1316365916, 0.05923646622, 0.00658182958> }
  finish { ambient 0.2824 diffuse 0.7176 phong 0.3 phong_size 40 } }
  no_shadow
  rotate <48.25939785, 32.94975699, 312.3648612>
  transform { Axis_Rotate_Trans(<0.8778115577, -0.4789666314, 0.00615102779>, 0 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
