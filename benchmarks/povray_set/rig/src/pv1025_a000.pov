// validation scene pv1025_a000 (seed 1025)
#version 3.7;
#declare NS = 1;
#declare NLT = 237;
#declare LINES = array[237] { 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214, 215, 216, 217, 218, 219, 220, 221, 222, 223, 224, 225, 226, 227, 228, 229, 230, 231, 232, 233, 234, 235, 236, 237, 238, 239, 240, 241, 242, 243, 244, 245, 246, 247, 248, 249, 250, 251, 252, 253, 254, 255, 256, 257, 258, 259, 260, 261, 262, 263, 264, 265, 266, 267, 268, 269, 270, 271, 272, 273, 274, 275, 276, 277, 278, 279, 280, 281, 282, 283, 284, 285, 286, 287, 288, 289, 290, 291, 292, 293, 294, 295, 296, 297, 298, 299, 300, 301, 302, 303, 304, 305 };
#declare LR = 1367.4498313904867;  // line rate, Hz
#declare TAU = 2.6668640018872467e-05;  // exposure, s
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
// film: 2416 x 4 samples spanning y/z in [-0.04444277135, 0.03053497617] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -14.00466899, 2013.930866>
  right <0, 151, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 15955.834
  pigment { function { max(0.002, min(0.98, 0.0437351 * (1 + 0.0189615 * ((y / 15955.834) - -0.006953897589) / 0.03748887376 + 0.182966 * sin(13.12849 * ((y / 15955.834) - -0.006953897589) / 0.03748887376 + 3.27926)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 7.533598058, 2866.462076> + 85993.9 * <0.3061693832, -0.2879402564, -0.9073867519> color rgb FL }
light_source { <0, 7.533598058, 2866.462076> + 85993.9 * <0.592396451, 0.1624258248, -0.7891034763> color rgb FL * 0.4784 }


// ball 0: plain
#declare C0_0 = <0, 7.533598058, 2866.462076>;  // mm
#declare V_0 = <-286.3853418, 409.424632, 142.7887555>;  // mm/s
#declare TC_0 = 0.13675090354857822;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.5274345535, 0.5158151325, 0.7135774925> }
  finish { ambient 0.3955 diffuse 0.6045 } }
  no_shadow
  rotate <204.7001906, 253.0637814, 21.38109238>
  transform { Axis_Rotate_Trans(<-0.4820836417, -0.4146398693, 0.771796049>, 0 * (T - TC_0)) }
  scale 23.72694282
  translate P_0 }
#end
