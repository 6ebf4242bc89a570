// validation scene pv0068 (seed 68)
#version 3.7;
#declare NS = 4;
#declare NLT = 35;
#declare LINES = array[35] { 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42 };
#declare LR = 74.16025725552355;  // line rate, Hz
#declare TAU = 0.013462168714157587;  // exposure, s
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
// film: 3024 x 4 samples spanning y/z in [-0.09865522687, 0.09947119747] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 0.3896090049, 954.9584382>
  right <0, 189.2025008, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 68033.249
  pigment { function { max(0.002, min(0.98, 0.532216 * (1 + -0.288829 * ((y / 68033.249) - 0.0004079853) / 0.09906321217 + 0.129219 * sin(11.700606 * ((y / 68033.249) - 0.0004079853) / 0.09906321217 + 3.65799)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 678.468257, 12183.3821> + 365501 * <0.5143143232, -0.8244642832, -0.2360919793> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, 678.468257, 12183.3821>;  // mm
#declare V_0 = <579.7523906, -591.5427471, 52.46453097>;  // mm/s
#declare TC_0 = 0.3371077842119806;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.1093169506, 0.1093169506, 0.1093169506>] [0.925 rgb <0.1093169506, 0.1093169506, 0.1093169506>] [0.935 rgb <0.00594113862, 0.00594113862, 0.00594113862>] [1.0 rgb <0.00594113862, 0.00594113862, 0.00594113862>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.1711 diffuse 0.8289 phong 0.2836 phong_size 40 } }
  no_shadow
  rotate <244.6099546, 316.6122876, 166.4708367>
  transform { Axis_Rotate_Trans(<0.9553523339, 0.01435037309, -0.2951202889>, 370.08048 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
