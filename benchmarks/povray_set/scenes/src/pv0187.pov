// validation scene pv0187 (seed 187)
#version 3.7;
#declare NS = 2;
#declare NLT = 49;
#declare LINES = array[49] { 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60 };
#declare LR = 346.1883830546959;  // line rate, Hz
#declare TAU = 0.0010968103496803935;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.114911 * sin(628.3185307 * T + 1.90363));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 2784 x 4 samples spanning y/z in [-0.06863948504, 0.03544438449] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -27.75096925, 1671.991877>
  right <0, 174.0273844, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 20741.406
  pigment { function { max(0.002, min(0.98, 0.779674 * (1 + -0.104135 * ((y / 20741.406) - -0.01659755028) / 0.05204193477 + 0.113175 * sin(8.5780207 * ((y / 20741.406) - -0.01659755028) / 0.05204193477 + 2.79019)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -76.11492613, 3823.357361> + 114701 * <0.2928668059, -0.5655200755, -0.7709838378> color rgb FL }
light_source { <0, -76.11492613, 3823.357361> + 114701 * <0.2749356555, 0.791961197, 0.5451677245> color rgb FL * 0.6249 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, -76.11492613, 3823.357361>;  // mm
#declare V_0 = <-593.0534344, 549.0117633, -287.1859074>;  // mm/s
#declare TC_0 = 0.10398962461519742;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.09163523194, 0.08959889345, 0.08348987799>] [0.5 rgb <0.09163523194, 0.08959889345, 0.08348987799>] [0.5 rgb <0.07636269329, 0.00814535395, 0.006109015463>] [1.0 rgb <0.07636269329, 0.00814535395, 0.006109015463>] } }
  finish { ambient 0.4427 diffuse 0.5573 phong 0.419 phong_size 40 } }
  no_shadow
  rotate <102.0622291, 75.25679205, 18.10631727>
  transform { Axis_Rotate_Trans(<0.2582655099, -0.1842687918, 0.9483374604>, 21.916365 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
