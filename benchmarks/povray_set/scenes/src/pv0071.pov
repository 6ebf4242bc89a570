// validation scene pv0071 (seed 71)
#version 3.7;
#declare NS = 1;
#declare NLT = 239;
#declare LINES = array[239] { 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214, 215, 216, 217, 218, 219, 220, 221, 222, 223, 224, 225, 226, 227, 228, 229, 230, 231, 232, 233, 234, 235, 236, 237, 238, 239, 240, 241, 242, 243, 244, 245, 246, 247, 248, 249, 250, 251, 252, 253, 254, 255, 256, 257, 258, 259, 260, 261, 262, 263, 264, 265, 266, 267, 268, 269, 270, 271, 272, 273, 274, 275, 276, 277, 278, 279, 280, 281, 282, 283, 284, 285, 286, 287, 288, 289, 290, 291, 292, 293, 294, 295, 296, 297, 298, 299, 300, 301, 302, 303, 304, 305, 306, 307, 308 };
#declare LR = 16767.09295369373;  // line rate, Hz
#declare TAU = 1.5296846140927402e-05;  // exposure, s
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
// film: 272 x 4 samples spanning y/z in [0.3680807956, 0.4142066438] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 640.5746366, 1637.696336>
  right <0, 75.54013264, 0>
  up <1, 0, 0>
  aperture 68.244354 blur_samples 19 focal_point <0, 3642.270627, 9311.8474> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 48327.555
  pigment { function { max(0.002, min(0.98, 0.570112 * (1 + 0.287532 * ((y / 48327.555) - 0.3911437197) / 0.02306292411 + 0 * sin(3.1688221 * ((y / 48327.555) - 0.3911437197) / 0.02306292411 + 6.09607)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 4751.10624, 12129.4424> + 363883 * <-0.1049948867, 0.4241575219, -0.8994812229> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, 4751.10624, 12129.4424>;  // mm
#declare V_0 = <-5296.866492, 5136.607185, -1376.934087>;  // mm/s
#declare TC_0 = 0.01127207921623432;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.2359455269, 0.2359455269, 0.2308162763>] [0.44 rgb <0.2359455269, 0.2359455269, 0.2308162763>] [0.46 rgb <0.1795237705, 0.2179931499, 0.03846937939>] [1.00 rgb <0.1795237705, 0.2179931499, 0.03846937939>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.1309 diffuse 0.8691 } }
  no_shadow
  rotate <293.5898849, 238.2568851, 84.11722561>
  transform { Axis_Rotate_Trans(<-0.4775883512, -0.8768159434, -0.05570608753>, 4807.1615 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
