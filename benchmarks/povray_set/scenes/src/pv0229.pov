// validation scene pv0229 (seed 229)
#version 3.7;
#declare NS = 1;
#declare NLT = 117;
#declare LINES = array[117] { 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150 };
#declare LR = 4196.331106318446;  // line rate, Hz
#declare TAU = 3.394793794835782e-05;  // exposure, s
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
// film: 576 x 4 samples spanning y/z in [-0.06354128229, 0.0440698366] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -13.02692582, 1338.0543>
  right <0, 143.9895203, 0>
  up <1, 0, 0>
  aperture 36.907041 blur_samples 19 focal_point <0, -48.87655342, 5020.3312> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 18066.755
  pigment { function { max(0.002, min(0.98, 0.0683719 * (1 + -0.256583 * ((y / 18066.755) - -0.009735722847) / 0.05380555944 + 0.0929577 * sin(3.4282109 * ((y / 18066.755) - -0.009735722847) / 0.05380555944 + 4.32244)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 63.9847106, 3978.448294> + 119353 * <0.9017814772, 0.4222099779, -0.09235205429> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, 63.9847106, 3978.448294>;  // mm
#declare V_0 = <-2583.257023, -267.6818182, 163.6521392>;  // mm/s
#declare TC_0 = 0.02192391345417785;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.7486375538, 0.7486375538, 0.7323628243>] [0.44 rgb <0.7486375538, 0.7486375538, 0.7323628243>] [0.46 rgb <0.56961553, 0.6916760008, 0.1220604707>] [1.00 rgb <0.56961553, 0.6916760008, 0.1220604707>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.3557 diffuse 0.6443 } }
  no_shadow
  rotate <197.7589165, 55.87463305, 218.6377744>
  transform { Axis_Rotate_Trans(<0.7076573836, 0.3156188237, 0.6321438013>, 2223.0654 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
