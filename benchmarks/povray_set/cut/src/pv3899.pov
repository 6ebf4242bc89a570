// validation scene pv3899 (seed 3899)
#version 3.7;
#declare NS = 1;
#declare NLT = 208;
#declare LINES = array[208] { 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214, 215, 216, 217, 218, 219, 220, 221, 222, 223, 224, 225, 226, 227, 228, 229, 230, 231, 232, 233, 234, 235, 236, 237, 238, 239, 240, 241, 242, 243, 244, 245, 246, 247, 248, 249, 250, 251, 252, 253, 254, 255, 256, 257, 258, 259, 260, 261, 262, 263, 264, 265, 266, 267, 268, 269, 270, 271, 272, 273, 274, 275, 276, 277, 278, 279, 280, 281, 282, 283, 284, 285, 286, 287, 288 };
#declare LR = 1134.2017683794702;  // line rate, Hz
#declare TAU = 5.305535252019894e-05;  // exposure, s
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
// film: 420 x 4 samples spanning y/z in [-0.02911274315, 0.002622929204] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -43.82182979, 3308.579658>
  right <0, 105, 0>
  up <1, 0, 0>
  aperture 19.389576 blur_samples 19 focal_point <0, -137.5418531, 10384.509> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 28423.539
  pigment { function { max(0.002, min(0.98, 0.598478 * (1 + 0.0182907 * ((y / 28423.539) - -0.01324490697) / 0.01586783618 + 0.06374 * sin(19.638004 * ((y / 28423.539) - -0.01324490697) / 0.01586783618 + 1.66979)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -158.4545365, 7796.821053> + 233905 * <0.5966448743, -0.3320543792, -0.7305852334> color rgb FL }
light_source { <0, -158.4545365, 7796.821053> + 233905 * <0.8929946878, -0.3348209872, 0.3007580326> color rgb FL * 0.5095 }


// ball 0: plain
#declare C0_0 = <0, -158.4545365, 7796.821053>;  // mm
#declare V_0 = <485.8406518, -84.66851449, 17.20324866>;  // mm/s
#declare TC_0 = 0.19308733781371526;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.2023306712, 0.09725148643, 0.1356205225> }
  finish { ambient 0.4955 diffuse 0.5045 phong 0.2801 phong_size 40 } }
  no_shadow
  rotate <272.2349468, 34.98601221, 329.7810589>
  transform { Axis_Rotate_Trans(<-0.7136682379, -0.4528311721, -0.5344357546>, 0 * (T - TC_0)) }
  scale 57.28461555
  translate P_0 }
#end
