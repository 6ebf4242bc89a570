// validation scene pv0101 (seed 101)
#version 3.7;
#declare NS = 1;
#declare NLT = 29;
#declare LINES = array[29] { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28 };
#declare LR = 4992.106565029732;  // line rate, Hz
#declare TAU = 1.6937175447331502e-05;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.0725894 * sin(628.3185307 * T + 2.04014));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 348 x 4 samples spanning y/z in [-0.04559897044, 0.05363918596] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 3.526604316, 877.2412402>
  right <0, 87.0558034, 0>
  up <1, 0, 0>
  aperture 87.390926 blur_samples 19 focal_point <0, 58.34910896, 14514.315> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 36005.308
  pigment { function { max(0.002, min(0.98, 0.0244949 * (1 + -0.397451 * ((y / 36005.308) - 0.004020107758) / 0.0496190782 + 0 * sin(24.073638 * ((y / 36005.308) - 0.004020107758) / 0.0496190782 + 1.9119)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -28.58165677, 9746.183836> + 292386 * <-0.4700597774, -0.0754591885, -0.8794030456> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, -28.58165677, 9746.183836>;  // mm
#declare V_0 = <32950.37884, 66.60139888, 1592.685362>;  // mm/s
#declare TC_0 = 0.001802846129737296;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.8005528089, 0.8005528089, 0.8005528089>] [0.925 rgb <0.8005528089, 0.8005528089, 0.8005528089>] [0.935 rgb <0.04350830483, 0.04350830483, 0.04350830483>] [1.0 rgb <0.04350830483, 0.04350830483, 0.04350830483>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.3248 diffuse 0.6752 } }
  no_shadow
  rotate <126.8420299, 86.38101461, 148.3440565>
  transform { Axis_Rotate_Trans(<0.5805743595, -0.8102821177, 0.07985175532>, 0 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
