// validation scene pv4309 (seed 4309)
#version 3.7;
#declare NS = 1;
#declare NLT = 213;
#declare LINES = array[213] { 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214, 215, 216, 217, 218, 219, 220, 221, 222, 223, 224, 225, 226, 227, 228, 229, 230, 231, 232, 233, 234, 235, 236, 237, 238, 239, 240, 241, 242, 243, 244, 245, 246, 247, 248, 249, 250, 251, 252, 253, 254, 255, 256, 257, 258, 259, 260, 261, 262, 263, 264, 265, 266, 267, 268, 269, 270, 271, 272, 273 };
#declare LR = 174425.6593428682;  // line rate, Hz
#declare TAU = 1.7985997047106077e-06;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.208246 * sin(628.3185307 * T + 4.47051));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 564 x 4 samples spanning y/z in [-0.02657568855, 0.0558201955] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 25.0217757, 1711.212006>
  right <0, 140.996826, 0>
  up <1, 0, 0>
  aperture 16.041472 blur_samples 19 focal_point <0, 15.00043834, 1025.8637> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 8070.3062
  pigment { function { max(0.002, min(0.98, 0.507061 * (1 + -0.244243 * ((y / 8070.3062) - 0.01462225348) / 0.04119794202 + 0.196876 * sin(16.638639 * ((y / 8070.3062) - 0.01462225348) / 0.04119794202 + 6.11803)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 53.64093121, 1418.549143> + 42556.5 * <-0.05907707072, -0.04616982939, -0.9971851616> color rgb FL }


// ball 0: golf
#declare C0_0 = <0, 53.64093121, 1418.549143>;  // mm
#declare V_0 = <36438.32871, 45403.84964, -3954.957428>;  // mm/s
#declare TC_0 = 0.0009574279416753037;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.2242263759, 0.2242263759, 0.2242263759> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.3748 diffuse 0.6252 phong 0.4699 phong_size 40 } }
  no_shadow
  rotate <261.5129562, 315.7835222, 192.1386768>
  transform { Axis_Rotate_Trans(<-0.5402789005, 0.144135781, 0.8290498093>, 0 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
