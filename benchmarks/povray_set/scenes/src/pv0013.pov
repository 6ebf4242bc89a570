// validation scene pv0013 (seed 13)
#version 3.7;
#declare NS = 1;
#declare NLT = 45;
#declare LINES = array[45] { 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55 };
#declare LR = 2030.6058472580683;  // line rate, Hz
#declare TAU = 6.561535689692208e-05;  // exposure, s
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
// film: 2960 x 4 samples spanning y/z in [-0.01633584503, 0.01638896105] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 0.1501356215, 5653.1211>
  right <0, 184.9972917, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 16335.874
  pigment { function { max(0.002, min(0.98, 0.829552 * (1 + -0.381067 * ((y / 16335.874) - 2.655800554e-05) / 0.01636240304 + 0.223513 * sin(15.188488 * ((y / 16335.874) - 2.655800554e-05) / 0.01636240304 + 0.455039)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -1.705415204, 4176.317577> + 125290 * <0.6685813957, -0.248563599, -0.7008673588> color rgb FL }
light_source { <0, -1.705415204, 4176.317577> + 125290 * <0.8915040097, -0.08705712134, 0.4445690703> color rgb FL * 0.6559 }


// ball 0: pingpong
#declare C0_0 = <0, -1.705415204, 4176.317577>;  // mm
#declare V_0 = <2062.392728, 619.1117471, -44.06884644>;  // mm/s
#declare TC_0 = 0.016251307482719985;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.2217192289, 0.099773653, 0.01108596144> }
  finish { ambient 0.4274 diffuse 0.5726 phong 0.3 phong_size 40 } }
  no_shadow
  rotate <164.5473126, 207.0451939, 231.7742367>
  transform { Axis_Rotate_Trans(<0.7121595067, 0.5905083089, -0.3796429562>, 1807.5374 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
