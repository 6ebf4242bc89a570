// validation scene pv0176 (seed 176)
#version 3.7;
#declare NS = 1;
#declare NLT = 113;
#declare LINES = array[113] { 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144 };
#declare LR = 37692.59038789163;  // line rate, Hz
#declare TAU = 2.3988883254664546e-06;  // exposure, s
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
// film: 2528 x 4 samples spanning y/z in [-0.3068096494, -0.2364110605] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -576.2463784, 2121.592082>
  right <0, 149.3570888, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 9177.4639
  pigment { function { max(0.002, min(0.98, 0.142566 * (1 + -0.329184 * ((y / 9177.4639) - -0.2716103549) / 0.03519929445 + 0 * sin(22.418275 * ((y / 9177.4639) - -0.2716103549) / 0.03519929445 + 1.00581)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -1018.575657, 3668.623085> + 110059 * <-0.2270613096, 0.9623189443, -0.1496175496> color rgb FL }
light_source { <0, -1018.575657, 3668.623085> + 110059 * <0.4149548947, 0.6834767026, -0.6005597659> color rgb FL * 0.6648 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, -1018.575657, 3668.623085>;  // mm
#declare V_0 = <-25878.42995, 8335.915098, 1836.476412>;  // mm/s
#declare TC_0 = 0.0023346763672753338;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.8720485877, 0.8526697302, 0.7945331576>] [0.5 rgb <0.8720485877, 0.8526697302, 0.7945331576>] [0.5 rgb <0.7267071564, 0.07751543001, 0.05813657251>] [1.0 rgb <0.7267071564, 0.07751543001, 0.05813657251>] } }
  finish { ambient 0.4428 diffuse 0.5572 phong 0.1 phong_size 40 } }
  no_shadow
  rotate <334.013404, 34.9860035, 234.8853597>
  transform { Axis_Rotate_Trans(<-0.2285736074, -0.4056310898, -0.8849957768>, 0 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
