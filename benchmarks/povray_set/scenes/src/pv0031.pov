// validation scene pv0031 (seed 31)
#version 3.7;
#declare NS = 4;
#declare NLT = 53;
#declare LINES = array[53] { 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66 };
#declare LR = 877.8293281140014;  // line rate, Hz
#declare TAU = 0.0007718658210581064;  // exposure, s
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
// film: 2656 x 4 samples spanning y/z in [-0.02830125597, 0.027013063] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -1.932824975, 3000.831415>
  right <0, 165.988946, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 17906.213
  pigment { function { max(0.002, min(0.98, 0.0617359 * (1 + -0.326231 * ((y / 17906.213) - -0.0006440964879) / 0.02765715948 + 0.0683665 * sin(16.783942 * ((y / 17906.213) - -0.0006440964879) / 0.02765715948 + 4.16867)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 76.63638037, 3407.810214> + 102234 * <-0.001496734516, 0.06250168296, -0.9980437362> color rgb FL }
light_source { <0, 76.63638037, 3407.810214> + 102234 * <-0.5900842473, 0.6283595843, -0.5069169695> color rgb FL * 0.6365 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, 76.63638037, 3407.810214>;  // mm
#declare V_0 = <1349.267948, -32.78552815, -576.0524527>;  // mm/s
#declare TC_0 = 0.04556694418713395;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.7681127772, 0.7510436044, 0.6998360859>] [0.5 rgb <0.7681127772, 0.7510436044, 0.6998360859>] [0.5 rgb <0.640093981, 0.06827669131, 0.05120751848>] [1.0 rgb <0.640093981, 0.06827669131, 0.05120751848>] } }
  finish { ambient 0.5271 diffuse 0.4729 phong 0.1 phong_size 40 } }
  no_shadow
  rotate <331.7260631, 352.5034547, 220.1576387>
  transform { Axis_Rotate_Trans(<0.07293126954, 0.8548161502, 0.5137804777>, 644.54719 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
