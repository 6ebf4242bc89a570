// validation scene pv0037 (seed 37)
#version 3.7;
#declare NS = 1;
#declare NLT = 183;
#declare LINES = array[183] { 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214, 215, 216, 217, 218, 219, 220, 221, 222, 223, 224, 225, 226, 227, 228, 229, 230, 231, 232, 233, 234 };
#declare LR = 8438.715749855777;  // line rate, Hz
#declare TAU = 3.615580717219772e-05;  // exposure, s
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
// film: 3008 x 4 samples spanning y/z in [0.06426037747, 0.1062160156] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 381.9458278, 4480.923381>
  right <0, 188, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 26899.597
  pigment { function { max(0.002, min(0.98, 0.1562 * (1 + -0.113653 * ((y / 26899.597) - 0.08523819655) / 0.02097781908 + 0 * sin(24.813313 * ((y / 26899.597) - 0.08523819655) / 0.02097781908 + 2.84487)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 910.378202, 8772.473375> + 263174 * <0.7400775503, 0.1749198645, -0.6493752848> color rgb FL }
light_source { <0, 910.378202, 8772.473375> + 263174 * <-0.6300956738, -0.6385360507, -0.4418723275> color rgb FL * 0.2086 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, 910.378202, 8772.473375>;  // mm
#declare V_0 = <-3560.987925, -99.71872159, 22.26610473>;  // mm/s
#declare TC_0 = 0.016945706460422483;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.8463884032, 0.827579772, 0.7711538785>] [0.5 rgb <0.8463884032, 0.827579772, 0.7711538785>] [0.5 rgb <0.7053236693, 0.07523452473, 0.05642589355>] [1.0 rgb <0.7053236693, 0.07523452473, 0.05642589355>] } }
  finish { ambient 0.1187 diffuse 0.8813 phong 0.2349 phong_size 40 } }
  no_shadow
  rotate <307.4363174, 90.50677742, 218.518917>
  transform { Axis_Rotate_Trans(<0.03327357257, 0.9161519849, 0.399447631>, 1507.0165 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
