// validation scene pv0224 (seed 224)
#version 3.7;
#declare NS = 1;
#declare NLT = 195;
#declare LINES = array[195] { 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214, 215, 216, 217, 218, 219, 220, 221, 222, 223, 224, 225, 226, 227, 228, 229, 230, 231, 232, 233, 234, 235, 236, 237, 238, 239, 240, 241, 242, 243, 244, 245, 246, 247, 248, 249, 250, 251 };
#declare LR = 5113.659914476276;  // line rate, Hz
#declare TAU = 5.920558773778826e-06;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.242041 * sin(753.9822369 * T + 3.32373));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 700 x 4 samples spanning y/z in [-0.05128438581, 0.04621636437] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -4.548189373, 1794.857985>
  right <0, 175, 0>
  up <1, 0, 0>
  aperture 43.586532 blur_samples 19 focal_point <0, -9.359896853, 3693.7085> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 32099.403
  pigment { function { max(0.002, min(0.98, 0.711707 * (1 + -0.20723 * ((y / 32099.403) - -0.002534010719) / 0.04875037509 + 0.129467 * sin(14.451884 * ((y / 32099.403) - -0.002534010719) / 0.04875037509 + 0.936404)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 183.0163675, 5912.850097> + 177386 * <-0.2941194072, -0.4239832139, -0.8565815832> color rgb FL }
light_source { <0, 183.0163675, 5912.850097> + 177386 * <-0.7013333786, 0.5696357561, 0.4285400769> color rgb FL * 0.2634 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, 183.0163675, 5912.850097>;  // mm
#declare V_0 = <-1876.530302, 850.4649007, 587.9436381>;  // mm/s
#declare TC_0 = 0.030115416859076004;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.1111950433, 0.1111950433, 0.1087777597>] [0.44 rgb <0.1111950433, 0.1111950433, 0.1087777597>] [0.46 rgb <0.08460492423, 0.1027345509, 0.01812962662>] [1.00 rgb <0.08460492423, 0.1027345509, 0.01812962662>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.3188 diffuse 0.6812 phong 0.5009 phong_size 40 } }
  no_shadow
  rotate <268.3869745, 41.68906738, 83.56033976>
  transform { Axis_Rotate_Trans(<-0.6894637248, 0.5579500753, -0.4618782151>, 0 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
