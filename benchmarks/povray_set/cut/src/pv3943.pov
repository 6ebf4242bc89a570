// validation scene pv3943 (seed 3943)
#version 3.7;
#declare NS = 1;
#declare NLT = 181;
#declare LINES = array[181] { 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214, 215, 216, 217, 218, 219, 220, 221, 222, 223, 224, 225, 226, 227, 228, 229, 230, 231 };
#declare LR = 6393.379435370964;  // line rate, Hz
#declare TAU = 4.951408889001863e-05;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.100788 * sin(753.9822369 * T + 4.88072));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 632 x 4 samples spanning y/z in [-0.04557634719, 0.04407768359] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -1.320356044, 1762.044592>
  right <0, 157.9744001, 0>
  up <1, 0, 0>
  aperture 12.919328 blur_samples 19 focal_point <0, -1.015988414, 1355.8592> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 6242.6761
  pigment { function { max(0.002, min(0.98, 0.0391021 * (1 + -0.023785 * ((y / 6242.6761) - -0.0007493317992) / 0.04482701539 + 0.0201285 * sin(11.351215 * ((y / 6242.6761) - -0.0007493317992) / 0.04482701539 + 6.15107)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -64.52619876, 1758.679607> + 52760.4 * <0.0260092951, 0.6530898383, -0.7568336539> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, -64.52619876, 1758.679607>;  // mm
#declare V_0 = <1705.452146, 2373.097402, 459.609177>;  // mm/s
#declare TC_0 = 0.022054064118254346;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.3411707065, 0.2089386734, 0.2391263912> }
  finish { ambient 0.4848 diffuse 0.5152 } }
  no_shadow
  rotate <74.98872654, 84.18055203, 273.7733467>
  transform { Axis_Rotate_Trans(<0.07947018263, 0.9016440647, -0.4251146559>, 372.92316 * (T - TC_0)) }
  scale 22.96390561
  translate P_0 }
#end
