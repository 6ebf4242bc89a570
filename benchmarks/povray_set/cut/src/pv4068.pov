// validation scene pv4068 (seed 4068)
#version 3.7;
#declare NS = 1;
#declare NLT = 67;
#declare LINES = array[67] { 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111 };
#declare LR = 14669.701543385967;  // line rate, Hz
#declare TAU = 2.943506479974785e-05;  // exposure, s
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
// film: 1872 x 4 samples spanning y/z in [-0.2708563787, -0.2195412969] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -559.0610595, 2280.031441>
  right <0, 117, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 54956.391
  pigment { function { max(0.002, min(0.98, 0.0248858 * (1 + -0.367105 * ((y / 54956.391) - -0.2451988378) / 0.02565754092 + 0.233385 * sin(16.00475 * ((y / 54956.391) - -0.2451988378) / 0.02565754092 + 1.19391)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -2479.307343, 10089.68532> + 302691 * <0.1974987097, 0.4422854897, -0.8748587345> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, -2479.307343, 10089.68532>;  // mm
#declare V_0 = <-7368.527862, 1515.367326, -163.1826825>;  // mm/s
#declare TC_0 = 0.008452796373073253;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.8310514796, 0.812583669, 0.757180237>] [0.5 rgb <0.8310514796, 0.812583669, 0.757180237>] [0.5 rgb <0.6925428997, 0.07387124263, 0.05540343197>] [1.0 rgb <0.6925428997, 0.07387124263, 0.05540343197>] } }
  finish { ambient 0.4825 diffuse 0.5175 phong 0.1 phong_size 40 } }
  no_shadow
  rotate <49.6963135, 71.54457867, 23.61063775>
  transform { Axis_Rotate_Trans(<0.5780430915, -0.2856675377, -0.7643691793>, 0 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
