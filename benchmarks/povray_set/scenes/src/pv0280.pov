// validation scene pv0280 (seed 280)
#version 3.7;
#declare NS = 1;
#declare NLT = 65;
#declare LINES = array[65] { 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82 };
#declare LR = 125.22004399942244;  // line rate, Hz
#declare TAU = 0.0004307420558983594;  // exposure, s
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
// film: 1344 x 4 samples spanning y/z in [-0.4138714787, -0.3595769771] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -598.3080092, 1547.117987>
  right <0, 84, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 9093.1121
  pigment { function { max(0.002, min(0.98, 0.0889671 * (1 + -0.0919425 * ((y / 9093.1121) - -0.3867242279) / 0.02714725079 + 0.0740856 * sin(10.219445 * ((y / 9093.1121) - -0.3867242279) / 0.02714725079 + 1.82772)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -667.5990176, 1819.69397> + 54590.8 * <0.0379842517, -0.5223889557, -0.8518608898> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, -667.5990176, 1819.69397>;  // mm
#declare V_0 = <-138.2678015, -26.26940777, 26.18920213>;  // mm/s
#declare TC_0 = 0.39929709655932255;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.6658481715, 0.6658481715, 0.6513732112>] [0.44 rgb <0.6658481715, 0.6658481715, 0.6513732112>] [0.46 rgb <0.5066236087, 0.6151858106, 0.1085622019>] [1.00 rgb <0.5066236087, 0.6151858106, 0.1085622019>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.3415 diffuse 0.6585 phong 0.4308 phong_size 40 } }
  no_shadow
  rotate <250.3506951, 282.3322937, 166.9596831>
  transform { Axis_Rotate_Trans(<0.2552169356, 0.4799235301, -0.839367453>, 0 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
