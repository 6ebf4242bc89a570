// validation scene pv0292 (seed 292)
#version 3.7;
#declare NS = 7;
#declare NLT = 37;
#declare LINES = array[37] { 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45 };
#declare LR = 5973.044997311968;  // line rate, Hz
#declare TAU = 0.00013694813854157886;  // exposure, s
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
// film: 1728 x 4 samples spanning y/z in [-0.0275134014, 0.02456810994] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -3.053510664, 2073.486243>
  right <0, 107.9902973, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 22268.501
  pigment { function { max(0.002, min(0.98, 0.0291073 * (1 + 0.278 * ((y / 22268.501) - -0.001472645731) / 0.02604075567 + 0 * sin(22.766525 * ((y / 22268.501) - -0.001472645731) / 0.02604075567 + 6.28302)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 36.31214645, 7072.39493> + 212172 * <0.2831687851, -0.4221858066, -0.8611472487> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, 36.31214645, 7072.39493>;  // mm
#declare V_0 = <-41688.50096, 1902.507977, 3502.483881>;  // mm/s
#declare TC_0 = 0.004520307483394271;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.712928081, 0.712928081, 0.712928081>] [0.925 rgb <0.712928081, 0.712928081, 0.712928081>] [0.935 rgb <0.03874609136, 0.03874609136, 0.03874609136>] [1.0 rgb <0.03874609136, 0.03874609136, 0.03874609136>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.5562 diffuse 0.4438 } }
  no_shadow
  rotate <11.53807985, 139.0194668, 259.1063341>
  transform { Axis_Rotate_Trans(<-0.9513761609, -0.2052378788, 0.2296972214>, 0 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
