// validation scene pv3449 (seed 3449)
#version 3.7;
#declare NS = 1;
#declare NLT = 112;
#declare LINES = array[112] { 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153 };
#declare LR = 3712.9641243323226;  // line rate, Hz
#declare TAU = 2.665301985645779e-05;  // exposure, s
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
// film: 1264 x 4 samples spanning y/z in [-0.00579817939, 0.008052973732] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 6.430105546, 5703.496258>
  right <0, 79, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 44089.459
  pigment { function { max(0.002, min(0.98, 0.143049 * (1 + -0.0207657 * ((y / 44089.459) - 0.001127397171) / 0.006925576561 + 0.182071 * sin(16.584875 * ((y / 44089.459) - 0.001127397171) / 0.006925576561 + 4.80168)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -29.59835142, 9438.347978> + 283150 * <0.047821457, -0.3908931444, -0.9191929383> color rgb FL }


// ball 0: pingpong
#declare C0_0 = <0, -29.59835142, 9438.347978>;  // mm
#declare V_0 = <-1077.362666, -134.3364912, -386.5533266>;  // mm/s
#declare TC_0 = 0.03097255889071637;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.8070013059, 0.8070013059, 0.8070013059> }
  finish { ambient 0.239 diffuse 0.761 phong 0.3 phong_size 40 } }
  no_shadow
  rotate <262.3471295, 117.5038803, 244.1854623>
  transform { Axis_Rotate_Trans(<0.01547972214, -0.4474401026, -0.8941799219>, 0 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
