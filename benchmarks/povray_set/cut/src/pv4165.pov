// validation scene pv4165 (seed 4165)
#version 3.7;
#declare NS = 1;
#declare NLT = 147;
#declare LINES = array[147] { 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189 };
#declare LR = 47143.452159503584;  // line rate, Hz
#declare TAU = 6.411061701429958e-07;  // exposure, s
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
// film: 2240 x 4 samples spanning y/z in [-0.4362847356, -0.3075160396] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -404.3378234, 1087.220764>
  right <0, 140, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 4829.0031
  pigment { function { max(0.002, min(0.98, 0.65944 * (1 + 0.179999 * ((y / 4829.0031) - -0.3719003876) / 0.06438434801 + 0.243629 * sin(19.69588 * ((y / 4829.0031) - -0.3719003876) / 0.06438434801 + 5.84543)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -477.7935006, 1507.187509> + 45215.6 * <-0.4988299902, 0.3911831072, -0.7733979684> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, -477.7935006, 1507.187509>;  // mm
#declare V_0 = <-22400.12503, 8257.505229, 623.7616308>;  // mm/s
#declare TC_0 = 0.0024605750042981465;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.1275790442, 0.1275790442, 0.1248055868>] [0.44 rgb <0.1275790442, 0.1275790442, 0.1248055868>] [0.46 rgb <0.09707101193, 0.1178719431, 0.02080093113>] [1.00 rgb <0.09707101193, 0.1178719431, 0.02080093113>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.5506 diffuse 0.4494 phong 0.5947 phong_size 40 } }
  no_shadow
  rotate <253.6677803, 257.3989634, 285.0352915>
  transform { Axis_Rotate_Trans(<0.3423022646, -0.2558966516, 0.9040719349>, 0 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
