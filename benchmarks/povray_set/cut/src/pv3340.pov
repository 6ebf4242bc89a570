// validation scene pv3340 (seed 3340)
#version 3.7;
#declare NS = 1;
#declare NLT = 158;
#declare LINES = array[158] { 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214 };
#declare LR = 109683.34157169661;  // line rate, Hz
#declare TAU = 1.7777884372343175e-06;  // exposure, s
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
// film: 1552 x 4 samples spanning y/z in [-0.006891939683, 0.008875763608] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 6.102059291, 6151.815405>
  right <0, 97, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 34120.991
  pigment { function { max(0.002, min(0.98, 0.0105417 * (1 + -0.0882792 * ((y / 34120.991) - 0.0009919119626) / 0.007883851645 + 0.110762 * sin(11.680508 * ((y / 34120.991) - 0.0009919119626) / 0.007883851645 + 5.94177)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 23.45487336, 6435.893345> + 193077 * <-0.1942491297, -0.3333624832, -0.9225707184> color rgb FL }


// ball 0: golf
#declare C0_0 = <0, 23.45487336, 6435.893345>;  // mm
#declare V_0 = <24681.4416, -22259.94744, -5223.24247>;  // mm/s
#declare TC_0 = 0.0014222761429822743;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.9246139611, 0.9246139611, 0.9246139611> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.5374 diffuse 0.4626 phong 0.7393 phong_size 40 } }
  no_shadow
  rotate <182.8492782, 40.49256302, 273.6882351>
  transform { Axis_Rotate_Trans(<-0.03557484822, 0.8226979324, 0.5673645585>, 10165.655 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
