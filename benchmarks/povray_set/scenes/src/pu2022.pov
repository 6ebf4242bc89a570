// validation scene pu2022 (seed 2022)
#version 3.7;
#declare NS = 3;
#declare NLT = 30;
#declare LINES = array[30] { 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37 };
#declare LR = 1613.8087705686214;  // line rate, Hz
#declare TAU = 0.00025702727525871497;  // exposure, s
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
// film: 1584 x 4 samples spanning y/z in [0.02987166179, 0.07963502774] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 108.92714, 1989.415268>
  right <0, 99, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 63005.163
  pigment { function { max(0.002, min(0.98, 0.015574 * (1 + 0.374055 * ((y / 63005.163) - 0.05475334476) / 0.02488168298 + 0.218141 * sin(18.572494 * ((y / 63005.163) - 0.05475334476) / 0.02488168298 + 2.78296)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 689.3094779, 10901.25912> + 327038 * <0.3106382669, 0.03470537438, -0.9498944173> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, 689.3094779, 10901.25912>;  // mm
#declare V_0 = <12159.78724, 7726.232245, 2769.033328>;  // mm/s
#declare TC_0 = 0.015491302597885444;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.8499105302, 0.8499105302, 0.8499105302> }
  finish { ambient 1 diffuse 0 } }
  no_shadow
  rotate <166.8314973, 313.3724719, 315.9749418>
  transform { Axis_Rotate_Trans(<-0.4368154257, 0.1137061984, -0.8923358024>, 0 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
