// validation scene pv3208 (seed 3208)
#version 3.7;
#declare NS = 1;
#declare NLT = 90;
#declare LINES = array[90] { 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119 };
#declare LR = 6739.288157411398;  // line rate, Hz
#declare TAU = 2.6404776134108717e-05;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.141204 * sin(628.3185307 * T + 4.92411));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 568 x 4 samples spanning y/z in [-0.06331482142, 0.05201810041] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -6.955732442, 1231.460428>
  right <0, 142.0279293, 0>
  up <1, 0, 0>
  aperture 73.763036 blur_samples 19 focal_point <0, -34.02823129, 6024.444> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 19803.979
  pigment { function { max(0.002, min(0.98, 0.567981 * (1 + -0.169051 * ((y / 19803.979) - -0.005648360502) / 0.05766646091 + 0 * sin(19.991098 * ((y / 19803.979) - -0.005648360502) / 0.05766646091 + 1.29074)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -38.27931428, 4273.501956> + 128205 * <0.6842898466, -0.7234590819, 0.09140220291> color rgb FL }
light_source { <0, -38.27931428, 4273.501956> + 128205 * <0.6362049984, -0.5753977229, 0.5139656219> color rgb FL * 0.2305 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, -38.27931428, 4273.501956>;  // mm
#declare V_0 = <14467.56806, 7093.6952, -7774.808139>;  // mm/s
#declare TC_0 = 0.012464224416286855;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.2437289213, 0.2437289213, 0.2437289213>] [0.925 rgb <0.2437289213, 0.2437289213, 0.2437289213>] [0.935 rgb <0.01324613703, 0.01324613703, 0.01324613703>] [1.0 rgb <0.01324613703, 0.01324613703, 0.01324613703>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.504 diffuse 0.496 phong 0.3152 phong_size 40 } }
  no_shadow
  rotate <57.46837169, 263.2144597, 356.41726>
  transform { Axis_Rotate_Trans(<0.2588408777, 0.9645874274, 0.05071976956>, 11353.116 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
