// validation scene pv0096 (seed 96)
#version 3.7;
#declare NS = 1;
#declare NLT = 108;
#declare LINES = array[108] { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107 };
#declare LR = 351.2326225927664;  // line rate, Hz
#declare TAU = 8.726198409893285e-05;  // exposure, s
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
// film: 1696 x 4 samples spanning y/z in [-0.0349678086, 0.002659830951] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -45.50928163, 2817.216362>
  right <0, 106.0052018, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 35283.02
  pigment { function { max(0.002, min(0.98, 0.772548 * (1 + 0.172851 * ((y / 35283.02) - -0.01615398883) / 0.01881381978 + 0.245356 * sin(23.582147 * ((y / 35283.02) - -0.01615398883) / 0.01881381978 + 0.961129)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -90.16243636, 6099.103197> + 182973 * <0.02864683634, -0.1942692107, -0.9805298734> color rgb FL }
light_source { <0, -90.16243636, 6099.103197> + 182973 * <0.8763252922, 0.4718865341, 0.09683533031> color rgb FL * 0.669 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, -90.16243636, 6099.103197>;  // mm
#declare V_0 = <-103.1705662, 80.70865839, 5.302940949>;  // mm/s
#declare TC_0 = -0.06548366672268695;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.1095052117, 0.1070717625, 0.09977141509>] [0.5 rgb <0.1095052117, 0.1070717625, 0.09977141509>] [0.5 rgb <0.09125434307, 0.009733796594, 0.007300347445>] [1.0 rgb <0.09125434307, 0.009733796594, 0.007300347445>] } }
  finish { ambient 0.4206 diffuse 0.5794 phong 0.1 phong_size 40 } }
  no_shadow
  rotate <151.5087747, 69.25762198, 69.34975945>
  transform { Axis_Rotate_Trans(<-0.8903838166, -0.2785962946, -0.3600010608>, 61.80723 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
