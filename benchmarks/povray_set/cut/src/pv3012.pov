// validation scene pv3012 (seed 3012)
#version 3.7;
#declare NS = 1;
#declare NLT = 109;
#declare LINES = array[109] { 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138 };
#declare LR = 919.5935779026456;  // line rate, Hz
#declare TAU = 0.0002179653696932496;  // exposure, s
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
// film: 488 x 4 samples spanning y/z in [0.157730531, 0.232666692] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 317.7935761, 1628.052442>
  right <0, 122, 0>
  up <1, 0, 0>
  aperture 107.29763 blur_samples 19 focal_point <0, 1925.114063, 9862.3348> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 24598.977
  pigment { function { max(0.002, min(0.98, 0.0438237 * (1 + -0.144914 * ((y / 24598.977) - 0.1951986115) / 0.03746808053 + 0 * sin(24.084435 * ((y / 24598.977) - 0.1951986115) / 0.03746808053 + 3.82055)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 1184.748015, 7432.243745> + 222967 * <-0.3616741457, -0.6683167377, -0.6500342686> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, 1184.748015, 7432.243745>;  // mm
#declare V_0 = <683.5385892, 31.44300086, 244.1231898>;  // mm/s
#declare TC_0 = 0.09134470054867304;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.7495671599, 0.7329101119, 0.6829389679>] [0.5 rgb <0.7495671599, 0.7329101119, 0.6829389679>] [0.5 rgb <0.6246392999, 0.06662819199, 0.04997114399>] [1.0 rgb <0.6246392999, 0.06662819199, 0.04997114399>] } }
  finish { ambient 0.2042 diffuse 0.7958 phong 0.1 phong_size 40 } }
  no_shadow
  rotate <294.955919, 27.74032702, 143.1290747>
  transform { Axis_Rotate_Trans(<0.1741661794, -0.562448324, -0.8082809071>, 430.95892 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
