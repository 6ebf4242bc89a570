// validation scene pv0136 (seed 136)
#version 3.7;
#declare NS = 1;
#declare NLT = 217;
#declare LINES = array[217] { 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214, 215, 216, 217, 218, 219, 220, 221, 222, 223, 224, 225, 226, 227, 228, 229, 230, 231, 232, 233, 234, 235, 236, 237, 238, 239, 240, 241, 242, 243, 244, 245, 246, 247, 248, 249, 250, 251, 252, 253, 254, 255, 256, 257, 258, 259, 260, 261, 262, 263, 264, 265, 266, 267, 268, 269, 270, 271, 272, 273, 274, 275, 276, 277, 278, 279 };
#declare LR = 114117.12365995653;  // line rate, Hz
#declare TAU = 6.690172216727107e-06;  // exposure, s
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
// film: 800 x 4 samples spanning y/z in [-0.01542457093, 0.01968260488] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 12.12867127, 5696.841041>
  right <0, 200, 0>
  up <1, 0, 0>
  aperture 10.882001 blur_samples 19 focal_point <0, 23.0475607, 10825.447> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 43763.067
  pigment { function { max(0.002, min(0.98, 0.482556 * (1 + 0.313983 * ((y / 43763.067) - 0.002129016973) / 0.0175535879 + 0 * sin(21.342028 * ((y / 43763.067) - 0.002129016973) / 0.0175535879 + 5.4566)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -124.7072494, 14668.79987> + 440064 * <-0.936215811, 0.2821094989, 0.2095571185> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, -124.7072494, 14668.79987>;  // mm
#declare V_0 = <18610.78696, -111.7465868, -9701.655479>;  // mm/s
#declare TC_0 = 0.001498460480913817;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.04873314769, 0.06834064924, 0.0691273869> }
  finish { ambient 0.1693 diffuse 0.8307 } }
  no_shadow
  rotate <55.44531522, 138.9423659, 41.21041526>
  transform { Axis_Rotate_Trans(<0.6059628637, -0.6104577105, -0.510049401>, 0 * (T - TC_0)) }
  scale 16.06226886
  translate P_0 }
#end
