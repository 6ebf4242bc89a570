// validation scene pv0275 (seed 275)
#version 3.7;
#declare NS = 1;
#declare NLT = 61;
#declare LINES = array[61] { 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76 };
#declare LR = 10335.371665732393;  // line rate, Hz
#declare TAU = 2.552463276884588e-05;  // exposure, s
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
// film: 416 x 4 samples spanning y/z in [0.1598284529, 0.2071469024] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 413.8946765, 2255.708295>
  right <0, 106.7366191, 0>
  up <1, 0, 0>
  aperture 17.989172 blur_samples 19 focal_point <0, 1125.058856, 6131.5227> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 32928.421
  pigment { function { max(0.002, min(0.98, 0.025404 * (1 + 0.388487 * ((y / 32928.421) - 0.1834876776) / 0.02365922476 + 0.0490067 * sin(10.063829 * ((y / 32928.421) - 0.1834876776) / 0.02365922476 + 0.533478)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 1802.206706, 9120.786906> + 273624 * <-0.5693978879, 0.1718950504, -0.803889381> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, 1802.206706, 9120.786906>;  // mm
#declare V_0 = <14061.03734, -13876.99644, 35.63550841>;  // mm/s
#declare TC_0 = 0.004450734960264277;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.7280983025, 0.7119183403, 0.6633784534>] [0.5 rgb <0.7280983025, 0.7119183403, 0.6633784534>] [0.5 rgb <0.6067485854, 0.06471984911, 0.04853988684>] [1.0 rgb <0.6067485854, 0.06471984911, 0.04853988684>] } }
  finish { ambient 0.3995 diffuse 0.6005 phong 0.1 phong_size 40 } }
  no_shadow
  rotate <331.5188577, 352.6513966, 148.1867114>
  transform { Axis_Rotate_Trans(<0.1109974709, -0.2078706185, -0.9718381385>, 0 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
