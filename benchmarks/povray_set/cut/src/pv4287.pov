// validation scene pv4287 (seed 4287)
#version 3.7;
#declare NS = 1;
#declare NLT = 121;
#declare LINES = array[121] { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120 };
#declare LR = 8164.235939937933;  // line rate, Hz
#declare TAU = 6.809368922513816e-05;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.16839 * sin(628.3185307 * T + 5.66748));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 560 x 4 samples spanning y/z in [-0.02177239033, 0.02793490539] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 8.678324741, 2816.487962>
  right <0, 140, 0>
  up <1, 0, 0>
  aperture 16.083606 blur_samples 19 focal_point <0, 11.11998347, 3608.9108> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 10969.682
  pigment { function { max(0.002, min(0.98, 0.217416 * (1 + 0.390571 * ((y / 10969.682) - 0.003081257531) / 0.02485364786 + 0.114427 * sin(15.601335 * ((y / 10969.682) - 0.003081257531) / 0.02485364786 + 5.81137)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -0.5054740131, 2938.540016> + 88156.2 * <-0.5286271876, -0.1620498938, -0.8332425388> color rgb FL }
light_source { <0, -0.5054740131, 2938.540016> + 88156.2 * <-0.1402799229, -0.9278149353, -0.3456602221> color rgb FL * 0.6207 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, -0.5054740131, 2938.540016>;  // mm
#declare V_0 = <-3239.418781, 216.1724472, -1234.919484>;  // mm/s
#declare TC_0 = 0.003919533957055542;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.803532068, 0.803532068, 0.7860639796>] [0.44 rgb <0.803532068, 0.803532068, 0.7860639796>] [0.46 rgb <0.6113830952, 0.7423937585, 0.1310106633>] [1.00 rgb <0.6113830952, 0.7423937585, 0.1310106633>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.2701 diffuse 0.7299 } }
  no_shadow
  rotate <185.4553371, 58.08789317, 277.2174037>
  transform { Axis_Rotate_Trans(<0.5155028776, -0.3703548663, 0.7727186138>, 0 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
