// validation scene pv0153 (seed 153)
#version 3.7;
#declare NS = 3;
#declare NLT = 115;
#declare LINES = array[115] { 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147 };
#declare LR = 706.3234193464918;  // line rate, Hz
#declare TAU = 0.001403832744434989;  // exposure, s
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
// film: 1904 x 4 samples spanning y/z in [-0.05129965954, 0.05606439691] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 2.640565969, 1108.37839>
  right <0, 119, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 7314.0087
  pigment { function { max(0.002, min(0.98, 0.0209397 * (1 + 0.3761 * ((y / 7314.0087) - 0.002382368687) / 0.05368202822 + 0.213793 * sin(15.793375 * ((y / 7314.0087) - 0.002382368687) / 0.05368202822 + 5.7284)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -113.2245725, 2060.242781> + 61807.3 * <-0.05769302634, -0.3583824149, -0.9317905126> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, -113.2245725, 2060.242781>;  // mm
#declare V_0 = <678.8197777, -80.29164023, -84.62376123>;  // mm/s
#declare TC_0 = 0.12742038212929463;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.2190390535, 0.5145411211, 0.7451679149> }
  finish { ambient 0.4017 diffuse 0.5983 phong 0.3399 phong_size 40 } }
  no_shadow
  rotate <17.9260609, 107.6867357, 118.241446>
  transform { Axis_Rotate_Trans(<0.001379304565, 0.8030905455, -0.595855413>, 14.908734 * (T - TC_0)) }
  scale 52.27910512
  translate P_0 }
#end
