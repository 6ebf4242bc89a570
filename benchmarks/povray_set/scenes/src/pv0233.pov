// validation scene pv0233 (seed 233)
#version 3.7;
#declare NS = 3;
#declare NLT = 51;
#declare LINES = array[51] { 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63 };
#declare LR = 2897.1719132036515;  // line rate, Hz
#declare TAU = 0.00022527930254809847;  // exposure, s
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
// film: 696 x 4 samples spanning y/z in [0.1142926572, 0.3049130269] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 191.3273727, 912.8090575>
  right <0, 174, 0>
  up <1, 0, 0>
  aperture 27.640152 blur_samples 19 focal_point <0, 374.4423136, 1786.4372> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 13501.078
  pigment { function { max(0.002, min(0.98, 0.0127086 * (1 + -0.201428 * ((y / 13501.078) - 0.209602842) / 0.09531018485 + 0.0478772 * sin(22.965219 * ((y / 13501.078) - 0.209602842) / 0.09531018485 + 2.38857)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 542.9856678, 2911.453894> + 87343.6 * <-0.1298305248, 0.1830247057, -0.9744978153> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, 542.9856678, 2911.453894>;  // mm
#declare V_0 = <4741.267166, -5266.802267, 81.9582041>;  // mm/s
#declare TC_0 = 0.013116239263130278;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.7188141828, 0.7028405343, 0.6549195888>] [0.5 rgb <0.7188141828, 0.7028405343, 0.6549195888>] [0.5 rgb <0.599011819, 0.06389459403, 0.04792094552>] [1.0 rgb <0.599011819, 0.06389459403, 0.04792094552>] } }
  finish { ambient 0.5743 diffuse 0.4257 phong 0.6576 phong_size 40 } }
  no_shadow
  rotate <178.0195582, 315.2676849, 79.45248268>
  transform { Axis_Rotate_Trans(<0.8323312202, -0.287761931, 0.4737275705>, 4984.6528 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
