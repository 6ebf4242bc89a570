// validation scene pv0262 (seed 262)
#version 3.7;
#declare NS = 1;
#declare NLT = 145;
#declare LINES = array[145] { 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185 };
#declare LR = 29080.631710766884;  // line rate, Hz
#declare TAU = 1.035742169839751e-06;  // exposure, s
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
// film: 1136 x 4 samples spanning y/z in [-0.01962819628, 0.02016397982] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 0.4779913432, 1784.27035>
  right <0, 71, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 25556.548
  pigment { function { max(0.002, min(0.98, 0.106666 * (1 + 0.314282 * ((y / 25556.548) - 0.0002678917705) / 0.01989608805 + 0 * sin(14.053795 * ((y / 25556.548) - 0.0002678917705) / 0.01989608805 + 3.4152)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -80.42189997, 9409.452492> + 282284 * <0.8827695236, -0.4652673582, -0.06514793624> color rgb FL }


// ball 0: pingpong
#declare C0_0 = <0, -80.42189997, 9409.452492>;  // mm
#declare V_0 = <-9362.31136, 1417.491376, -967.3731903>;  // mm/s
#declare TC_0 = 0.0038857477761792434;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.6765846879, 0.6765846879, 0.6765846879> }
  finish { ambient 0.2 diffuse 0.8 phong 0.3037 phong_size 40 } }
  no_shadow
  rotate <259.3905639, 285.5963475, 319.8965168>
  transform { Axis_Rotate_Trans(<-0.4956854814, 0.6647824371, 0.5588919527>, 7.7554671 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
