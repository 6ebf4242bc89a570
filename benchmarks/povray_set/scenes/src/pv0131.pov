// validation scene pv0131 (seed 131)
#version 3.7;
#declare NS = 2;
#declare NLT = 51;
#declare LINES = array[51] { 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64 };
#declare LR = 176.94676455960624;  // line rate, Hz
#declare TAU = 0.0009740219569690269;  // exposure, s
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
// film: 416 x 4 samples spanning y/z in [-0.02194229339, 0.02247532464] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 0.6240232165, 2341.413263>
  right <0, 104, 0>
  up <1, 0, 0>
  aperture 5.9717055 blur_samples 19 focal_point <0, 0.7749382964, 2907.6655> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 9625.9763
  pigment { function { max(0.002, min(0.98, 0.702611 * (1 + -0.218946 * ((y / 9625.9763) - 0.0002665156238) / 0.02220880902 + 0 * sin(15.629082 * ((y / 9625.9763) - 0.0002665156238) / 0.02220880902 + 2.12948)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 2.545761133, 2205.650801> + 66169.5 * <0.03002045551, 0.09334862587, -0.9951807908> color rgb FL }
light_source { <0, 2.545761133, 2205.650801> + 66169.5 * <-0.6219702976, 0.09352479563, -0.7774355674> color rgb FL * 0.6375 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, 2.545761133, 2205.650801>;  // mm
#declare V_0 = <-274.4548466, -41.97339053, -142.3999195>;  // mm/s
#declare TC_0 = 0.2204052732869409;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.2414970195, 0.2361304191, 0.2200306178>] [0.5 rgb <0.2414970195, 0.2361304191, 0.2200306178>] [0.5 rgb <0.2012475163, 0.02146640173, 0.0160998013>] [1.0 rgb <0.2012475163, 0.02146640173, 0.0160998013>] } }
  finish { ambient 0.226 diffuse 0.774 phong 0.2564 phong_size 40 } }
  no_shadow
  rotate <228.2491493, 242.1119141, 188.9759056>
  transform { Axis_Rotate_Trans(<0.5982322778, 0.7225439368, 0.3464800156>, 169.38554 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
