// validation scene pv0283 (seed 283)
#version 3.7;
#declare NS = 2;
#declare NLT = 67;
#declare LINES = array[67] { 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84 };
#declare LR = 80.79594700043147;  // line rate, Hz
#declare TAU = 0.011432773097964179;  // exposure, s
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
// film: 1104 x 4 samples spanning y/z in [-0.3672526373, -0.3315775452] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -675.8116066, 1934.122548>
  right <0, 69, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 18071.835
  pigment { function { max(0.002, min(0.98, 0.0216412 * (1 + 0.202394 * ((y / 18071.835) - -0.3494150912) / 0.01783754604 + 0.0595745 * sin(4.1821425 * ((y / 18071.835) - -0.3494150912) / 0.01783754604 + 2.30697)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -1719.440547, 4964.741833> + 148942 * <0.8450687862, -0.009678623295, -0.5345699868> color rgb FL }


// ball 0: pingpong
#declare C0_0 = <0, -1719.440547, 4964.741833>;  // mm
#declare V_0 = <-55.18571919, 50.98345371, 12.452661>;  // mm/s
#declare TC_0 = 0.6312197813552164;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.8070031584, 0.3631514213, 0.04035015792> }
  finish { ambient 0.5958 diffuse 0.4042 phong 0.3 phong_size 40 } }
  no_shadow
  rotate <205.0262496, 145.6298725, 205.2272346>
  transform { Axis_Rotate_Trans(<0.8209446837, 0.4809630751, 0.3077732066>, 0 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
