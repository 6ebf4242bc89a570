// validation scene pv1107_a030 (seed 1107)
#version 3.7;
#declare NS = 1;
#declare NLT = 81;
#declare LINES = array[81] { 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102 };
#declare LR = 38205.704267726986;  // line rate, Hz
#declare TAU = 1.8142992174641582e-05;  // exposure, s
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
// film: 2784 x 4 samples spanning y/z in [-0.08018577092, 0.07167355662] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -4.876635867, 1145.797251>
  right <0, 174, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 56467.928
  pigment { function { max(0.002, min(0.98, 0.135068 * (1 + 0.137887 * ((y / 56467.928) - -0.004256107146) / 0.07592966377 + 0 * sin(17.17522 * ((y / 56467.928) - -0.004256107146) / 0.07592966377 + 3.41848)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 714.8173593, 11070.93231> + 332128 * <0.6748055319, 0.7120445178, -0.1939847901> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, 714.8173593, 11070.93231>;  // mm
#declare V_0 = <38377.21707, -11468.92078, -3595.353865>;  // mm/s
#declare TC_0 = 0.001622794323212423;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.8979653617, 0.8979653617, 0.8784443756>] [0.44 rgb <0.8979653617, 0.8979653617, 0.8784443756>] [0.46 rgb <0.6832345143, 0.8296419103, 0.1464073959>] [1.00 rgb <0.6832345143, 0.8296419103, 0.1464073959>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.3614 diffuse 0.6386 } }
  no_shadow
  rotate <339.7807686, 141.8205359, 148.8889431>
  transform { Axis_Rotate_Trans(<-0.7712794302, 0.6154445209, 0.1623455644>, 10873.094 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
