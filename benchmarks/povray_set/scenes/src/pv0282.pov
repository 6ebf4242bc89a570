// validation scene pv0282 (seed 282)
#version 3.7;
#declare NS = 1;
#declare NLT = 59;
#declare LINES = array[59] { 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73 };
#declare LR = 10539.954464453998;  // line rate, Hz
#declare TAU = 1.34530808732939e-05;  // exposure, s
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
// film: 2176 x 4 samples spanning y/z in [-0.04199812998, 0.03644848284] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -4.808408978, 1732.870165>
  right <0, 135.9377949, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 14694.393
  pigment { function { max(0.002, min(0.98, 0.0253921 * (1 + 0.392424 * ((y / 14694.393) - -0.002774823569) / 0.03922330641 + 0.00213305 * sin(8.5313758 * ((y / 14694.393) - -0.002774823569) / 0.03922330641 + 0.87392)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 39.58460716, 3275.739148> + 98272.2 * <0.5238080642, -0.5631009464, -0.6391732442> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, 39.58460716, 3275.739148>;  // mm
#declare V_0 = <-14591.59436, 2346.195338, -1525.30317>;  // mm/s
#declare TC_0 = 0.0041745910903495855;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.6630210511, 0.64828725, 0.6040858466>] [0.5 rgb <0.6630210511, 0.64828725, 0.6040858466>] [0.5 rgb <0.5525175426, 0.05893520454, 0.04420140341>] [1.0 rgb <0.5525175426, 0.05893520454, 0.04420140341>] } }
  finish { ambient 0.1576 diffuse 0.8424 phong 0.3541 phong_size 40 } }
  no_shadow
  rotate <30.22649875, 240.1272278, 171.9310954>
  transform { Axis_Rotate_Trans(<0.7928151577, 0.5545287893, 0.2528674505>, 1475.658 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
