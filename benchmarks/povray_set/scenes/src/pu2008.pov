// validation scene pu2008 (seed 2008)
#version 3.7;
#declare NS = 5;
#declare NLT = 49;
#declare LINES = array[49] { 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60 };
#declare LR = 289.1790187525564;  // line rate, Hz
#declare TAU = 0.0017462386052691707;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.266043 * sin(753.9822369 * T + 0.264533));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 2416 x 4 samples spanning y/z in [-0.0515771383, -0.0258461939] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -226.8680452, 5860.456758>
  right <0, 150.795087, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 21197.778
  pigment { function { max(0.002, min(0.98, 0.233751 * (1 + 0.0147799 * ((y / 21197.778) - -0.0387116661) / 0.0128654722 + 0.0574173 * sin(6.2924348 * ((y / 21197.778) - -0.0387116661) / 0.0128654722 + 1.89331)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -188.8227706, 4682.827169> + 140485 * <-0.3475852117, 0.5405052374, -0.7661844484> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, -188.8227706, 4682.827169>;  // mm
#declare V_0 = <-286.5045233, -378.3122324, 34.87409034>;  // mm/s
#declare TC_0 = 0.12449035948491251;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.8685444023, 0.8685444023, 0.8685444023> }
  finish { ambient 1 diffuse 0 } }
  no_shadow
  rotate <171.6441774, 220.4038517, 77.98388556>
  transform { Axis_Rotate_Trans(<-0.09661763562, 0.5461469176, -0.8320988985>, 0 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
