// validation scene pu2039 (seed 2039)
#version 3.7;
#declare NS = 1;
#declare NLT = 207;
#declare LINES = array[207] { 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214, 215, 216, 217, 218, 219, 220, 221, 222, 223, 224, 225, 226, 227, 228, 229, 230, 231, 232, 233, 234, 235, 236, 237, 238, 239, 240, 241, 242, 243, 244, 245, 246, 247, 248, 249, 250, 251, 252, 253, 254, 255, 256, 257, 258, 259, 260, 261, 262, 263, 264, 265 };
#declare LR = 39751.062678182214;  // line rate, Hz
#declare TAU = 1.981298440518597e-06;  // exposure, s
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
// film: 772 x 4 samples spanning y/z in [0.3026928593, 0.3947920716] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 759.9492711, 2179.113089>
  right <0, 200.6945989, 0>
  up <1, 0, 0>
  aperture 176.5555 blur_samples 19 focal_point <0, 6869.496703, 19697.907> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 87086.53
  pigment { function { max(0.002, min(0.98, 0.0574298 * (1 + 0.0657596 * ((y / 87086.53) - 0.3487424654) / 0.04604960612 + 0.10646 * sin(17.215978 * ((y / 87086.53) - 0.3487424654) / 0.04604960612 + 2.92171)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 4774.962155, 14674.89223> + 440247 * <-0.4408662903, 0.07882515384, -0.8941048647> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, 4774.962155, 14674.89223>;  // mm
#declare V_0 = <-14500.27191, 11376.0664, -3028.001701>;  // mm/s
#declare TC_0 = 0.004075362747193056;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.6231456862, 0.7566769047, 0.1335312185> }
  finish { ambient 1 diffuse 0 } }
  no_shadow
  rotate <167.0786615, 3.107486976, 275.3432032>
  transform { Axis_Rotate_Trans(<0.1833433532, -0.6634912591, 0.7253720176>, 6226.7895 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
