// validation scene pv3990 (seed 3990)
#version 3.7;
#declare NS = 1;
#declare NLT = 155;
#declare LINES = array[155] { 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198 };
#declare LR = 297.191413433878;  // line rate, Hz
#declare TAU = 0.002733862358259803;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.30546 * sin(753.9822369 * T + 1.87991));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 352 x 4 samples spanning y/z in [-0.005630065031, 0.008291528802] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 8.411778681, 6321.167151>
  right <0, 88.00072164, 0>
  up <1, 0, 0>
  aperture 6.5338346 blur_samples 19 focal_point <0, 16.13721873, 12126.574> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 48788.092
  pigment { function { max(0.002, min(0.98, 0.12874 * (1 + -0.265227 * ((y / 48788.092) - 0.001330731885) / 0.006960796917 + 0 * sin(14.366189 * ((y / 48788.092) - 0.001330731885) / 0.006960796917 + 4.85951)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 56.44315997, 8525.021501> + 255751 * <0.5259153204, 0.8391245649, -0.1388633873> color rgb FL }


// ball 0: pingpong
#declare C0_0 = <0, 56.44315997, 8525.021501>;  // mm
#declare V_0 = <-81.82730114, -64.76337875, -49.39934021>;  // mm/s
#declare TC_0 = 0.4071450066538388;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.9930658975, 0.4468796539, 0.04965329487> }
  finish { ambient 0.1725 diffuse 0.8275 phong 0.6967 phong_size 40 } }
  no_shadow
  rotate <242.2271337, 56.30037878, 252.0432042>
  transform { Axis_Rotate_Trans(<0.292032815, -0.8670675945, -0.4036218795>, 39.343269 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
