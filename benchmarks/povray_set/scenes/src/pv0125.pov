// validation scene pv0125 (seed 125)
#version 3.7;
#declare NS = 1;
#declare NLT = 125;
#declare LINES = array[125] { 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159 };
#declare LR = 154.73230686389695;  // line rate, Hz
#declare TAU = 0.00021409860222650024;  // exposure, s
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
// film: 2656 x 4 samples spanning y/z in [-0.01925215469, 0.02022527097] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 2.045945246, 4204.934775>
  right <0, 166, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 78273.995
  pigment { function { max(0.002, min(0.98, 0.0900534 * (1 + 0.331218 * ((y / 78273.995) - 0.0004865581408) / 0.01973871283 + 0.21382 * sin(16.285586 * ((y / 78273.995) - 0.0004865581408) / 0.01973871283 + 4.31)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -37.6338327, 14844.81302> + 445344 * <0.5358051285, -0.3001102604, -0.7892063709> color rgb FL }
light_source { <0, -37.6338327, 14844.81302> + 445344 * <0.6193244947, 0.6790264662, 0.3941576187> color rgb FL * 0.6491 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, -37.6338327, 14844.81302>;  // mm
#declare V_0 = <-90.91214258, 43.86291061, 16.82444428>;  // mm/s
#declare TC_0 = 0.6268891220326827;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.7242568973, 0.7242568973, 0.7085121821>] [0.44 rgb <0.7242568973, 0.7242568973, 0.7085121821>] [0.46 rgb <0.5510650305, 0.6691503942, 0.1180853637>] [1.00 rgb <0.5510650305, 0.6691503942, 0.1180853637>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.4076 diffuse 0.5924 phong 0.4054 phong_size 40 } }
  no_shadow
  rotate <44.41493277, 259.1281085, 301.7916471>
  transform { Axis_Rotate_Trans(<-0.7873788235, 0.2607650298, -0.5586019939>, 0 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
