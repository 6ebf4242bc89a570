// validation scene pv3216 (seed 3216)
#version 3.7;
#declare NS = 1;
#declare NLT = 89;
#declare LINES = array[89] { 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128 };
#declare LR = 148.16589804452587;  // line rate, Hz
#declare TAU = 0.006318395910930317;  // exposure, s
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
// film: 2864 x 4 samples spanning y/z in [-0.3804661868, -0.2811923217] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -596.5158747, 1803.092886>
  right <0, 179, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 10019.94
  pigment { function { max(0.002, min(0.98, 0.0193298 * (1 + 0.145796 * ((y / 10019.94) - -0.3308292542) / 0.04963693258 + 0.0112143 * sin(23.656915 * ((y / 10019.94) - -0.3308292542) / 0.04963693258 + 3.45907)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -1490.42441, 4524.201342> + 135726 * <-0.4434063609, 0.4695915641, -0.7634622204> color rgb FL }
light_source { <0, -1490.42441, 4524.201342> + 135726 * <-0.5430237175, 0.8378964287, 0.0552703983> color rgb FL * 0.5923 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, -1490.42441, 4524.201342>;  // mm
#declare V_0 = <76.36657787, 15.34792097, -9.522652887>;  // mm/s
#declare TC_0 = 0.7356618590280741;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.9073560709, 0.9073560709, 0.887630939>] [0.44 rgb <0.9073560709, 0.9073560709, 0.887630939>] [0.46 rgb <0.6903796192, 0.838318109, 0.1479384898>] [1.00 rgb <0.6903796192, 0.838318109, 0.1479384898>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.2174 diffuse 0.7826 } }
  no_shadow
  rotate <247.9271008, 69.51601229, 96.04734327>
  transform { Axis_Rotate_Trans(<-0.05287872529, -0.8347231427, 0.5481250911>, 36.249668 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
