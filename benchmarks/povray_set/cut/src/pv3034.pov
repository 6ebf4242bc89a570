// validation scene pv3034 (seed 3034)
#version 3.7;
#declare NS = 1;
#declare NLT = 58;
#declare LINES = array[58] { 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91 };
#declare LR = 1713.804437284451;  // line rate, Hz
#declare TAU = 2.1751207611716127e-05;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.100551 * sin(628.3185307 * T + 3.60829));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 352 x 4 samples spanning y/z in [-0.04238978575, 0.03358041111] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -5.102165062, 1158.348979>
  right <0, 88, 0>
  up <1, 0, 0>
  aperture 66.902453 blur_samples 19 focal_point <0, -30.97609298, 7032.5294> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 15830.927
  pigment { function { max(0.002, min(0.98, 0.0323952 * (1 + 0.0471503 * ((y / 15830.927) - -0.00440468732) / 0.03798509843 + 0 * sin(4.6117327 * ((y / 15830.927) - -0.00440468732) / 0.03798509843 + 1.94214)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -57.89381561, 4725.839907> + 141775 * <-0.8088200625, -0.5850498526, -0.05938666956> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, -57.89381561, 4725.839907>;  // mm
#declare V_0 = <3245.537275, 721.7523345, 166.6274778>;  // mm/s
#declare TC_0 = 0.05543222898321405;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.7065464141, 0.7065464141, 0.7065464141>] [0.925 rgb <0.7065464141, 0.7065464141, 0.7065464141>] [0.935 rgb <0.03839926164, 0.03839926164, 0.03839926164>] [1.0 rgb <0.03839926164, 0.03839926164, 0.03839926164>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.3073 diffuse 0.6927 } }
  no_shadow
  rotate <73.20638771, 214.8601838, 92.76821684>
  transform { Axis_Rotate_Trans(<-0.9973528922, 0.005126292759, -0.0725322649>, 1437.7382 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
