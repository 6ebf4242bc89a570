// validation scene pv0252 (seed 252)
#version 3.7;
#declare NS = 1;
#declare NLT = 93;
#declare LINES = array[93] { 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118 };
#declare LR = 487.74450752171833;  // line rate, Hz
#declare TAU = 0.00012698873900247434;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.218335 * sin(628.3185307 * T + 5.78284));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 2704 x 4 samples spanning y/z in [-0.05594789342, 0.1109678349] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 27.83841839, 1011.939222>
  right <0, 168.9085722, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 6597.9839
  pigment { function { max(0.002, min(0.98, 0.0162004 * (1 + 0.389879 * ((y / 6597.9839) - 0.02750997074) / 0.08345786416 + 0 * sin(15.272629 * ((y / 6597.9839) - 0.02750997074) / 0.08345786416 + 6.12105)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 61.5472038, 1524.478245> + 45734.3 * <0.2883514127, -0.05053208774, -0.9561903424> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, 61.5472038, 1524.478245>;  // mm
#declare V_0 = <409.7342348, -635.8996739, -50.42506493>;  // mm/s
#declare TC_0 = 0.1476182691750639;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.7606061843, 0.7437038247, 0.6929967457>] [0.5 rgb <0.7606061843, 0.7437038247, 0.6929967457>] [0.5 rgb <0.6338384869, 0.06760943861, 0.05070707896>] [1.0 rgb <0.6338384869, 0.06760943861, 0.05070707896>] } }
  finish { ambient 0.5906 diffuse 0.4094 phong 0.5291 phong_size 40 } }
  no_shadow
  rotate <134.843013, 126.1154436, 1.772794353>
  transform { Axis_Rotate_Trans(<-0.131591549, -0.770861105, 0.6232630433>, 0 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
