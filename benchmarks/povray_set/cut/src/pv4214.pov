// validation scene pv4214 (seed 4214)
#version 3.7;
#declare NS = 2;
#declare NLT = 139;
#declare LINES = array[139] { 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178 };
#declare LR = 1878.5451870312172;  // line rate, Hz
#declare TAU = 0.0003976334435361482;  // exposure, s
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
// film: 1456 x 4 samples spanning y/z in [-0.03017179463, 0.02750045679] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -2.107147353, 1577.597054>
  right <0, 90.98357391, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 6868.6299
  pigment { function { max(0.002, min(0.98, 0.0123022 * (1 + 0.244696 * ((y / 6868.6299) - -0.00133566892) / 0.02883612571 + 0 * sin(8.9812971 * ((y / 6868.6299) - -0.00133566892) / 0.02883612571 + 0.044653)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -40.13519865, 1414.687086> + 42440.6 * <-0.1784441645, 0.45389417, -0.8730050187> color rgb FL }


// ball 0: golf
#declare C0_0 = <0, -40.13519865, 1414.687086>;  // mm
#declare V_0 = <-605.6118956, 189.6169652, -126.7327219>;  // mm/s
#declare TC_0 = 0.058023624213298555;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.8385930964, 0.8385930964, 0.8385930964> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.2144 diffuse 0.7856 phong 0.35 phong_size 40 } }
  no_shadow
  rotate <236.8838444, 299.7689307, 135.7737986>
  transform { Axis_Rotate_Trans(<-0.1763580945, -0.1188874308, 0.9771200547>, 0 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
