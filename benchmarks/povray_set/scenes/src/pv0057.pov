// validation scene pv0057 (seed 57)
#version 3.7;
#declare NS = 1;
#declare NLT = 129;
#declare LINES = array[129] { 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164 };
#declare LR = 154087.58070676116;  // line rate, Hz
#declare TAU = 3.411206038771541e-07;  // exposure, s
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
// film: 640 x 4 samples spanning y/z in [-0.06766243246, 0.05223486325] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -10.29385633, 1334.47547>
  right <0, 160, 0>
  up <1, 0, 0>
  aperture 39.878306 blur_samples 19 focal_point <0, -15.84575762, 2054.2131> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 11291.273
  pigment { function { max(0.002, min(0.98, 0.845403 * (1 + -0.163712 * ((y / 11291.273) - -0.007713784604) / 0.05994864785 + 0.0831717 * sin(17.91542 * ((y / 11291.273) - -0.007713784604) / 0.05994864785 + 3.36284)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -46.2416302, 2477.65211> + 74329.6 * <-0.4742414051, -0.2705066925, -0.8378073877> color rgb FL }
light_source { <0, -46.2416302, 2477.65211> + 74329.6 * <-0.7195927983, 0.5405602764, -0.4358678609> color rgb FL * 0.2656 }


// ball 0: golf
#declare C0_0 = <0, -46.2416302, 2477.65211>;  // mm
#declare V_0 = <55047.53527, 41771.44034, -4581.946406>;  // mm/s
#declare TC_0 = 0.0006489815697107128;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.1609352992, 0.1609352992, 0.1609352992> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.1622 diffuse 0.8378 phong 0.35 phong_size 40 } }
  no_shadow
  rotate <162.147374, 266.9056639, 219.8054862>
  transform { Axis_Rotate_Trans(<-0.8649515701, -0.1165360114, -0.4881374186>, 12914.593 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
