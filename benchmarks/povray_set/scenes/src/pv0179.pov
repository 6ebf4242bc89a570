// validation scene pv0179 (seed 179)
#version 3.7;
#declare NS = 1;
#declare NLT = 55;
#declare LINES = array[55] { 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69 };
#declare LR = 351.25246110969044;  // line rate, Hz
#declare TAU = 0.0005366755406968764;  // exposure, s
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
// film: 324 x 4 samples spanning y/z in [0.09630331633, 0.1119911454] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 541.7920481, 5202.174303>
  right <0, 81.6108213, 0>
  up <1, 0, 0>
  aperture 80.053435 blur_samples 19 focal_point <0, 1138.782699, 10934.354> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 40278.213
  pigment { function { max(0.002, min(0.98, 0.610399 * (1 + 0.194268 * ((y / 40278.213) - 0.1041472309) / 0.007843914539 + 0 * sin(19.170639 * ((y / 40278.213) - 0.1041472309) / 0.007843914539 + 4.77382)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 1291.529312, 12922.63895> + 387679 * <-0.2344426353, 0.4662270653, -0.8530351542> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, 1291.529312, 12922.63895>;  // mm
#declare V_0 = <-473.0218452, 262.6574893, -4.942532016>;  // mm/s
#declare TC_0 = 0.11957211592856024;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.1485131924, 0.1485131924, 0.1452846447>] [0.44 rgb <0.1485131924, 0.1485131924, 0.1452846447>] [0.46 rgb <0.1129991681, 0.1372132756, 0.02421410745>] [1.00 rgb <0.1129991681, 0.1372132756, 0.02421410745>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.5342 diffuse 0.4658 phong 0.6525 phong_size 40 } }
  no_shadow
  rotate <34.77432795, 164.9103297, 52.23160052>
  transform { Axis_Rotate_Trans(<-0.4095465835, 0.6956909464, -0.5901573544>, 0 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
