// validation scene pv1013_a000 (seed 1013)
#version 3.7;
#declare NS = 2;
#declare NLT = 75;
#declare LINES = array[75] { 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95 };
#declare LR = 6268.601096425937;  // line rate, Hz
#declare TAU = 7.902338275396903e-05;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.332036 * sin(753.9822369 * T + 2.69603));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 2496 x 4 samples spanning y/z in [-0.07909453459, 0.1136817323] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 13.99446862, 809.2282445>
  right <0, 156, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 4503.2415
  pigment { function { max(0.002, min(0.98, 0.615319 * (1 + 0.269955 * ((y / 4503.2415) - 0.01729359883) / 0.09638813342 + 0.0900352 * sin(4.5417527 * ((y / 4503.2415) - 0.01729359883) / 0.09638813342 + 4.74852)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 67.76790802, 1261.64409> + 37849.3 * <0.567492682, 0.8089581471, 0.1534235058> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, 67.76790802, 1261.64409>;  // mm
#declare V_0 = <-6589.165035, -1095.175797, 380.704586>;  // mm/s
#declare TC_0 = 0.00925246304683016;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.1051069463, 0.1027712364, 0.0957641066>] [0.5 rgb <0.1051069463, 0.1027712364, 0.0957641066>] [0.5 rgb <0.08758912189, 0.009342839669, 0.007007129752>] [1.0 rgb <0.08758912189, 0.009342839669, 0.007007129752>] } }
  finish { ambient 0.2895 diffuse 0.7105 phong 0.4878 phong_size 40 } }
  no_shadow
  rotate <323.8361786, 319.3164528, 92.99785218>
  transform { Axis_Rotate_Trans(<0.7950793014, -0.2698834547, -0.5431499105>, 0 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
