// validation scene pv1093_a090 (seed 1093)
#version 3.7;
#declare NS = 1;
#declare NLT = 243;
#declare LINES = array[243] { 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214, 215, 216, 217, 218, 219, 220, 221, 222, 223, 224, 225, 226, 227, 228, 229, 230, 231, 232, 233, 234, 235, 236, 237, 238, 239, 240, 241, 242, 243, 244, 245, 246, 247, 248, 249, 250, 251, 252, 253, 254, 255, 256, 257, 258, 259, 260, 261, 262, 263, 264, 265, 266, 267, 268, 269, 270, 271, 272, 273, 274, 275, 276, 277, 278, 279, 280, 281, 282, 283, 284, 285, 286, 287, 288, 289, 290, 291, 292, 293, 294, 295, 296, 297, 298, 299, 300, 301, 302, 303, 304, 305, 306, 307, 308, 309, 310, 311, 312 };
#declare LR = 532.0915816853468;  // line rate, Hz
#declare TAU = 0.0003939448595082603;  // exposure, s
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
// film: 1616 x 4 samples spanning y/z in [-0.03132915613, 0.02323483194] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -7.491449695, 1851.037719>
  right <0, 101, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 9659.2439
  pigment { function { max(0.002, min(0.98, 0.693947 * (1 + 0.350654 * ((y / 9659.2439) - -0.004047162097) / 0.02728199404 + 0.0733893 * sin(9.5937724 * ((y / 9659.2439) - -0.004047162097) / 0.02728199404 + 1.66337)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -41.56515248, 3839.082906> + 115172 * <-0.4503722724, 0.7716264903, 0.4491741041> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, -41.56515248, 3839.082906>;  // mm
#declare V_0 = <-262.8833223, -57.20974009, 20.74899074>;  // mm/s
#declare TC_0 = 0.3589607627225122;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.1345724208, 0.1601098161, 0.1345453262> }
  finish { ambient 0.524 diffuse 0.476 phong 0.3227 phong_size 40 } }
  no_shadow
  rotate <179.8677319, 51.64528519, 256.1977121>
  transform { Axis_Rotate_Trans(<-0.3507920307, 0.2811760456, -0.8932440778>, 80.158835 * (T - TC_0)) }
  scale 57.739641
  translate P_0 }
#end
