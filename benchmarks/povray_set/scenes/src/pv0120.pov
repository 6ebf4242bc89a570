// validation scene pv0120 (seed 120)
#version 3.7;
#declare NS = 1;
#declare NLT = 115;
#declare LINES = array[115] { 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147 };
#declare LR = 58310.047640902434;  // line rate, Hz
#declare TAU = 2.676228581801357e-06;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.255171 * sin(628.3185307 * T + 2.43114));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 1984 x 4 samples spanning y/z in [-0.282496526, -0.2410849807] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -783.8889663, 2994.334048>
  right <0, 124, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 13050.201
  pigment { function { max(0.002, min(0.98, 0.0191098 * (1 + -0.158025 * ((y / 13050.201) - -0.2617907533) / 0.02070577264 + 0 * sin(23.007919 * ((y / 13050.201) - -0.2617907533) / 0.02070577264 + 3.01636)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -881.1878869, 3395.657036> + 101870 * <-0.4707332821, -0.2233430881, -0.8535385417> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, -881.1878869, 3395.657036>;  // mm
#declare V_0 = <-38777.22653, 5055.572312, -2084.747999>;  // mm/s
#declare TC_0 = 0.0015434732716093373;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.6965402505, 0.6810615783, 0.6346255616>] [0.5 rgb <0.6965402505, 0.6810615783, 0.6346255616>] [0.5 rgb <0.5804502088, 0.06191468893, 0.0464360167>] [1.0 rgb <0.5804502088, 0.06191468893, 0.0464360167>] } }
  finish { ambient 0.372 diffuse 0.628 phong 0.5369 phong_size 40 } }
  no_shadow
  rotate <134.7076973, 359.4181622, 79.8805152>
  transform { Axis_Rotate_Trans(<0.4989205755, -0.6841379116, 0.5320090012>, 9766.6363 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
