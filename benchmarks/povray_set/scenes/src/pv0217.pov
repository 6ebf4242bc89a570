// validation scene pv0217 (seed 217)
#version 3.7;
#declare NS = 1;
#declare NLT = 87;
#declare LINES = array[87] { 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110 };
#declare LR = 4952.307572862202;  // line rate, Hz
#declare TAU = 2.9692105559091978e-05;  // exposure, s
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
// film: 1888 x 4 samples spanning y/z in [-0.07431790688, -0.01353249868] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -85.2700357, 1941.255369>
  right <0, 118, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 18632.921
  pigment { function { max(0.002, min(0.98, 0.0343078 * (1 + 0.379384 * ((y / 18632.921) - -0.04392520278) / 0.0303927041 + 0 * sin(10.957983 * ((y / 18632.921) - -0.04392520278) / 0.0303927041 + 0.0755594)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -420.8444721, 8282.993805> + 248490 * <-0.43083279, -0.740066009, -0.5164159267> color rgb FL }
light_source { <0, -420.8444721, 8282.993805> + 248490 * <0.650722149, 0.7362755905, 0.1856311924> color rgb FL * 0.31 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, -420.8444721, 8282.993805>;  // mm
#declare V_0 = <4646.911138, -2956.798755, 509.544817>;  // mm/s
#declare TC_0 = 0.013529046613976187;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.8247767825, 0.8064484096, 0.7514632907>] [0.5 rgb <0.8247767825, 0.8064484096, 0.7514632907>] [0.5 rgb <0.6873139854, 0.07331349178, 0.05498511883>] [1.0 rgb <0.6873139854, 0.07331349178, 0.05498511883>] } }
  finish { ambient 0.2483 diffuse 0.7517 phong 0.2377 phong_size 40 } }
  no_shadow
  rotate <124.7424589, 33.88597098, 128.047094>
  transform { Axis_Rotate_Trans(<0.9104401121, 0.332238701, 0.2464066716>, 1318.3693 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
