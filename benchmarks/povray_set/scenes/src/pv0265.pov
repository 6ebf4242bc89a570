// validation scene pv0265 (seed 265)
#version 3.7;
#declare NS = 1;
#declare NLT = 81;
#declare LINES = array[81] { 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102 };
#declare LR = 500.38533263258614;  // line rate, Hz
#declare TAU = 0.0013917030796129933;  // exposure, s
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
// film: 1856 x 4 samples spanning y/z in [-0.0556806687, 0.0682241352] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 5.871612995, 936.2026035>
  right <0, 116, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 24256.375
  pigment { function { max(0.002, min(0.98, 0.0506187 * (1 + -0.331133 * ((y / 24256.375) - 0.006271733247) / 0.06195240195 + 0 * sin(24.456052 * ((y / 24256.375) - 0.006271733247) / 0.06195240195 + 2.1288)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -306.3938233, 8204.455458> + 246134 * <0.4890664986, 0.371630052, -0.7891166355> color rgb FL }
light_source { <0, -306.3938233, 8204.455458> + 246134 * <0.6770070556, -0.05147185601, -0.7341744307> color rgb FL * 0.3798 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, -306.3938233, 8204.455458>;  // mm
#declare V_0 = <-1496.213742, 210.168441, -122.4875807>;  // mm/s
#declare TC_0 = 0.12390451109709931;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.8072514493, 0.8072514493, 0.8072514493>] [0.925 rgb <0.8072514493, 0.8072514493, 0.8072514493>] [0.935 rgb <0.04387236137, 0.04387236137, 0.04387236137>] [1.0 rgb <0.04387236137, 0.04387236137, 0.04387236137>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.2254 diffuse 0.7746 } }
  no_shadow
  rotate <168.9449101, 5.26131613, 325.8404477>
  transform { Axis_Rotate_Trans(<0.09412523789, -0.9660478114, -0.2406077008>, 1005.1346 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
