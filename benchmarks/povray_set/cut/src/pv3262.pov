// validation scene pv3262 (seed 3262)
#version 3.7;
#declare NS = 1;
#declare NLT = 56;
#declare LINES = array[56] { 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81 };
#declare LR = 22.296267070911885;  // line rate, Hz
#declare TAU = 0.011641340800689112;  // exposure, s
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
// film: 1584 x 4 samples spanning y/z in [-0.1988085401, -0.1133670583] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -181.3478726, 1161.832465>
  right <0, 99.2686874, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 23428.731
  pigment { function { max(0.002, min(0.98, 0.0928463 * (1 + 0.366898 * ((y / 23428.731) - -0.1560877992) / 0.04272074089 + 0 * sin(18.972439 * ((y / 23428.731) - -0.1560877992) / 0.04272074089 + 5.11996)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -1434.596579, 7897.140271> + 236914 * <-0.04169965908, -0.5963336275, -0.801652882> color rgb FL }
light_source { <0, -1434.596579, 7897.140271> + 236914 * <0.1195507756, -0.9155597162, -0.3840026277> color rgb FL * 0.6968 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, -1434.596579, 7897.140271>;  // mm
#declare V_0 = <-55.69271319, 18.26405133, -1.261110411>;  // mm/s
#declare TC_0 = 3.274090670327372;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.9160614828, 0.9160614828, 0.9160614828>] [0.925 rgb <0.9160614828, 0.9160614828, 0.9160614828>] [0.935 rgb <0.04978595015, 0.04978595015, 0.04978595015>] [1.0 rgb <0.04978595015, 0.04978595015, 0.04978595015>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.2082 diffuse 0.7918 } }
  no_shadow
  rotate <153.8875873, 194.6924569, 322.0453307>
  transform { Axis_Rotate_Trans(<0.3066736871, 0.8097820167, -0.5002042934>, 24.878952 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
