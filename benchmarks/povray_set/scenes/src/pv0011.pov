// validation scene pv0011 (seed 11)
#version 3.7;
#declare NS = 3;
#declare NLT = 43;
#declare LINES = array[43] { 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53 };
#declare LR = 30204.7206898195;  // line rate, Hz
#declare TAU = 2.311595631348054e-05;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.289262 * sin(628.3185307 * T + 2.83412));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 2688 x 4 samples spanning y/z in [-0.2424143208, -0.2247431503] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -2220.635443, 9507.010291>
  right <0, 168, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 61468.729
  pigment { function { max(0.002, min(0.98, 0.138331 * (1 + -0.280656 * ((y / 61468.729) - -0.2335787355) / 0.008835585261 + 0 * sin(5.703386 * ((y / 61468.729) - -0.2335787355) / 0.008835585261 + 1.028)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -2896.150383, 12559.95456> + 376799 * <0.3996010216, -0.6817775816, -0.612779204> color rgb FL }


// ball 0: golf
#declare C0_0 = <0, -2896.150383, 12559.95456>;  // mm
#declare V_0 = <-34768.4205, 13761.99857, -1327.560644>;  // mm/s
#declare TC_0 = 0.0010594370439182905;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.7508394975, 0.7508394975, 0.7508394975> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.1594 diffuse 0.8406 phong 0.35 phong_size 40 } }
  no_shadow
  rotate <203.020204, 54.8469074, 49.78468641>
  transform { Axis_Rotate_Trans(<0.01953077468, -0.9514566372, 0.3071625242>, 5036.599 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
