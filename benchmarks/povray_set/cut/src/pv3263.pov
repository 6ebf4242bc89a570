// validation scene pv3263 (seed 3263)
#version 3.7;
#declare NS = 1;
#declare NLT = 93;
#declare LINES = array[93] { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92 };
#declare LR = 4482.500367710171;  // line rate, Hz
#declare TAU = 1.3576547941898645e-05;  // exposure, s
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
// film: 728 x 4 samples spanning y/z in [0.2604027152, 0.3478355309] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 614.9140554, 2021.951297>
  right <0, 176.784895, 0>
  up <1, 0, 0>
  aperture 106.70343 blur_samples 19 focal_point <0, 2825.20218, 9289.788> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 17528.887
  pigment { function { max(0.002, min(0.98, 0.0135861 * (1 + -0.350664 * ((y / 17528.887) - 0.3041191231) / 0.04371640782 + 0 * sin(10.01391 * ((y / 17528.887) - 0.3041191231) / 0.04371640782 + 1.58757)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 2272.46122, 6958.407294> + 208752 * <-0.4284164138, -0.5141617744, -0.7430323318> color rgb FL }
light_source { <0, 2272.46122, 6958.407294> + 208752 * <-0.1142525505, 0.7662804801, -0.632266226> color rgb FL * 0.3902 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, 2272.46122, 6958.407294>;  // mm
#declare V_0 = <7575.188743, -1216.72363, 656.346612>;  // mm/s
#declare TC_0 = 0.005354154608192502;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.7862303524, 0.7862303524, 0.7862303524>] [0.925 rgb <0.7862303524, 0.7862303524, 0.7862303524>] [0.935 rgb <0.04272991046, 0.04272991046, 0.04272991046>] [1.0 rgb <0.04272991046, 0.04272991046, 0.04272991046>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.4163 diffuse 0.5837 } }
  no_shadow
  rotate <29.44012676, 59.6881491, 110.8015091>
  transform { Axis_Rotate_Trans(<0.5216156977, -0.2726730947, -0.8084345659>, 996.78806 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
