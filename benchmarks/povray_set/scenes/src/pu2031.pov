// validation scene pu2031 (seed 2031)
#version 3.7;
#declare NS = 1;
#declare NLT = 257;
#declare LINES = array[257] { 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214, 215, 216, 217, 218, 219, 220, 221, 222, 223, 224, 225, 226, 227, 228, 229, 230, 231, 232, 233, 234, 235, 236, 237, 238, 239, 240, 241, 242, 243, 244, 245, 246, 247, 248, 249, 250, 251, 252, 253, 254, 255, 256, 257, 258, 259, 260, 261, 262, 263, 264, 265, 266, 267, 268, 269, 270, 271, 272, 273, 274, 275, 276, 277, 278, 279, 280, 281, 282, 283, 284, 285, 286, 287, 288, 289, 290, 291, 292, 293, 294, 295, 296, 297, 298, 299, 300, 301, 302, 303, 304, 305, 306, 307, 308, 309, 310, 311, 312, 313, 314, 315, 316, 317, 318, 319, 320, 321, 322, 323, 324, 325, 326, 327, 328, 329, 330, 331 };
#declare LR = 54105.656828874715;  // line rate, Hz
#declare TAU = 7.161564386797586e-07;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.195159 * sin(628.3185307 * T + 0.17532));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 752 x 4 samples spanning y/z in [-0.0598633921, 0.05820859414] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -1.317425182, 1592.248983>
  right <0, 188, 0>
  up <1, 0, 0>
  aperture 234.71078 blur_samples 19 focal_point <0, -14.78812878, 17873.032> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 71566.741
  pigment { function { max(0.002, min(0.98, 0.0571769 * (1 + 0.263411 * ((y / 71566.741) - -0.0008273989788) / 0.05903599312 + 0.0364186 * sin(5.6429778 * ((y / 71566.741) - -0.0008273989788) / 0.05903599312 + 5.654)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 469.0769055, 14187.52823> + 425626 * <0.1044133385, 0.4947275801, -0.8627528477> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, 469.0769055, 14187.52823>;  // mm
#declare V_0 = <-49052.31042, -18498.73469, 3312.831071>;  // mm/s
#declare TC_0 = 0.0037519182262595588;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.7714808197, 0.7714808197, 0.7714808197> }
  finish { ambient 1 diffuse 0 } }
  no_shadow
  rotate <343.8762821, 202.3053108, 216.4652929>
  transform { Axis_Rotate_Trans(<-0.3063833531, 0.9255319841, 0.2225304189>, 1089.5431 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
