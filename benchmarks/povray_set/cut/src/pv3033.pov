// validation scene pv3033 (seed 3033)
#version 3.7;
#declare NS = 1;
#declare NLT = 197;
#declare LINES = array[197] { 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214, 215, 216, 217, 218, 219, 220, 221, 222, 223, 224, 225, 226, 227, 228, 229, 230, 231, 232, 233, 234, 235, 236, 237, 238, 239, 240, 241, 242, 243, 244, 245, 246, 247, 248, 249, 250, 251, 252 };
#declare LR = 19091.42903703653;  // line rate, Hz
#declare TAU = 7.087516557371832e-06;  // exposure, s
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
// film: 420 x 4 samples spanning y/z in [-0.006802059333, 0.004625655285] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -9.998605702, 9188.188848>
  right <0, 105, 0>
  up <1, 0, 0>
  aperture 15.507587 blur_samples 19 focal_point <0, -23.70643952, 21784.962> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 75546.045
  pigment { function { max(0.002, min(0.98, 0.559144 * (1 + 0.31276 * ((y / 75546.045) - -0.001088202024) / 0.005713857309 + 0 * sin(16.279864 * ((y / 75546.045) - -0.001088202024) / 0.005713857309 + 4.77576)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -98.22489412, 14764.44672> + 442933 * <-0.1179588602, 0.02598392405, -0.9926784691> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, -98.22489412, 14764.44672>;  // mm
#declare V_0 = <7430.474195, -2859.163986, 181.3745202>;  // mm/s
#declare TC_0 = 0.008066446974778409;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.1802191187, 0.1762142494, 0.1641996415>] [0.5 rgb <0.1802191187, 0.1762142494, 0.1641996415>] [0.5 rgb <0.1501825989, 0.01601947722, 0.01201460791>] [1.0 rgb <0.1501825989, 0.01601947722, 0.01201460791>] } }
  finish { ambient 0.548 diffuse 0.452 phong 0.1 phong_size 40 } }
  no_shadow
  rotate <317.5924323, 299.0515057, 74.49118141>
  transform { Axis_Rotate_Trans(<-0.02382772364, 0.153050153, 0.9879311162>, 2385.1846 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
