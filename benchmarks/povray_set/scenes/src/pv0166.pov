// validation scene pv0166 (seed 166)
#version 3.7;
#declare NS = 1;
#declare NLT = 201;
#declare LINES = array[201] { 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214, 215, 216, 217, 218, 219, 220, 221, 222, 223, 224, 225, 226, 227, 228, 229, 230, 231, 232, 233, 234, 235, 236, 237, 238, 239, 240, 241, 242, 243, 244, 245, 246, 247, 248, 249, 250, 251, 252, 253, 254, 255, 256, 257, 258 };
#declare LR = 50.64252590157627;  // line rate, Hz
#declare TAU = 0.0012928264074213646;  // exposure, s
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
// film: 2848 x 4 samples spanning y/z in [-0.09404877085, 0.09706773246] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 1.405883737, 931.3690703>
  right <0, 178, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 41328.385
  pigment { function { max(0.002, min(0.98, 0.577616 * (1 + -0.358073 * ((y / 41328.385) - 0.001509480808) / 0.09555825166 + 0 * sin(3.1698224 * ((y / 41328.385) - 0.001509480808) / 0.09555825166 + 4.49566)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -250.9732056, 9119.635293> + 273589 * <-0.1608948144, -0.188812963, -0.9687427541> color rgb FL }
light_source { <0, -250.9732056, 9119.635293> + 273589 * <0.4439016761, 0.7555353209, -0.4817859284> color rgb FL * 0.3211 }


// ball 0: plain
#declare C0_0 = <0, -250.9732056, 9119.635293>;  // mm
#declare V_0 = <-51.71556446, -78.86916428, 0.2034385507>;  // mm/s
#declare TC_0 = 3.1199075714958004;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.09391161206, 0.02549321471, 0.09889485084> }
  finish { ambient 0.4787 diffuse 0.5213 } }
  no_shadow
  rotate <298.9411405, 197.6277655, 283.2143603>
  transform { Axis_Rotate_Trans(<-0.5845629878, -0.8072480954, 0.08146548848>, 48.663976 * (T - TC_0)) }
  scale 95.32903161
  translate P_0 }
#end
