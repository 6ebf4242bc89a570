// validation scene pv0228 (seed 228)
#version 3.7;
#declare NS = 1;
#declare NLT = 167;
#declare LINES = array[167] { 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214 };
#declare LR = 1707.343166502252;  // line rate, Hz
#declare TAU = 5.534149851868604e-05;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.317555 * sin(753.9822369 * T + 2.29314));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 2064 x 4 samples spanning y/z in [-0.1661089424, -0.0837269885] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -197.3155226, 1579.560809>
  right <0, 130.1273058, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 20917.078
  pigment { function { max(0.002, min(0.98, 0.0338551 * (1 + 0.284369 * ((y / 20917.078) - -0.1249179654) / 0.04119097694 + 0 * sin(22.036726 * ((y / 20917.078) - -0.1249179654) / 0.04119097694 + 0.898561)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -544.9077391, 6343.126767> + 190294 * <-0.07242030245, 0.8729136294, -0.482469787> color rgb FL }
light_source { <0, -544.9077391, 6343.126767> + 190294 * <0.3318549253, -0.8950335261, -0.2979719712> color rgb FL * 0.5156 }


// ball 0: plain
#declare C0_0 = <0, -544.9077391, 6343.126767>;  // mm
#declare V_0 = <-2285.734324, -363.3286465, -818.7134207>;  // mm/s
#declare TC_0 = 0.07672739878554884;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.6696775691, 0.6577997555, 0.3065747349> }
  finish { ambient 0.2103 diffuse 0.7897 phong 0.2728 phong_size 40 } }
  no_shadow
  rotate <245.0280711, 139.0004683, 228.0733803>
  transform { Axis_Rotate_Trans(<0.01862449973, -0.2088891546, -0.9777619593>, 2113.3504 * (T - TC_0)) }
  scale 106.9584332
  translate P_0 }
#end
