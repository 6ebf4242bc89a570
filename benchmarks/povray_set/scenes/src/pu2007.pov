// validation scene pu2007 (seed 2007)
#version 3.7;
#declare NS = 1;
#declare NLT = 71;
#declare LINES = array[71] { 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103 };
#declare LR = 1699.0438196318196;  // line rate, Hz
#declare TAU = 4.7244793901317215e-05;  // exposure, s
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
// film: 1696 x 4 samples spanning y/z in [0.2118221918, 0.3337837049] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 237.1003097, 869.1266395>
  right <0, 106, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 10288.287
  pigment { function { max(0.002, min(0.98, 0.557662 * (1 + 0.176914 * ((y / 10288.287) - 0.2728029484) / 0.06098075654 + 0.0924708 * sin(4.585467 * ((y / 10288.287) - 0.2728029484) / 0.06098075654 + 2.29617)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 813.4449977, 3279.572037> + 98387.2 * <0.2417541291, -0.5421498617, -0.8047536694> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, 813.4449977, 3279.572037>;  // mm
#declare V_0 = <3637.017942, 1114.516032, 334.8341581>;  // mm/s
#declare TC_0 = 0.02354265354301924;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.08121788447, 0.09862171685, 0.01740383239> }
  finish { ambient 1 diffuse 0 } }
  no_shadow
  rotate <146.3154885, 302.2574593, 176.5049412>
  transform { Axis_Rotate_Trans(<0.8508970163, -0.2707054829, -0.4502141815>, 1790.3772 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
// ball 1: plain
#declare C0_1 = <0, 967.1048808, 3154.316994>;  // mm
#declare V_1 = <4077.753055, -304.8580132, -417.7774646>;  // mm/s
#declare TC_1 = 0.051049637598699404;  // s
#declare P_1 = C0_1 + V_1 * (T - TC_1);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.08121788447, 0.09862171685, 0.01740383239> }
  finish { ambient 1 diffuse 0 } }
  no_shadow
  rotate <307.626586, 285.8069988, 355.4371084>
  transform { Axis_Rotate_Trans(<0.8508970163, -0.2707054829, -0.4502141815>, 1790.3772 * (T - TC_1)) }
  scale 33.5
  translate P_1 }
#end
