// validation scene pv0214 (seed 214)
#version 3.7;
#declare NS = 2;
#declare NLT = 115;
#declare LINES = array[115] { 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146 };
#declare LR = 2919.39953013062;  // line rate, Hz
#declare TAU = 0.00016113120197596217;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.224577 * sin(753.9822369 * T + 4.55679));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 1552 x 4 samples spanning y/z in [-0.0872246081, -0.05597655988] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -221.5684348, 3094.505973>
  right <0, 96.69727183, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 20564.97
  pigment { function { max(0.002, min(0.98, 0.0146802 * (1 + -0.176434 * ((y / 20564.97) - -0.07160058399) / 0.01562402411 + 0.155783 * sin(9.8575105 * ((y / 20564.97) - -0.07160058399) / 0.01562402411 + 0.224344)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -259.0963289, 3508.821611> + 105265 * <0.6100263338, -0.313839578, -0.7275799553> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, -259.0963289, 3508.821611>;  // mm
#declare V_0 = <1973.017169, -19.34849354, -670.0380129>;  // mm/s
#declare TC_0 = 0.030485721149656402;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.6374633887, 0.7332852457, 0.6343984862> }
  finish { ambient 0.199 diffuse 0.801 } }
  no_shadow
  rotate <187.8702313, 286.9959604, 335.0335492>
  transform { Axis_Rotate_Trans(<0.2696209033, 0.7605883984, 0.5906012672>, 1322.2543 * (T - TC_0)) }
  scale 36.59884723
  translate P_0 }
#end
