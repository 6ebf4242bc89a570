// validation scene pv0114 (seed 114)
#version 3.7;
#declare NS = 1;
#declare NLT = 85;
#declare LINES = array[85] { 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108 };
#declare LR = 1102.5356368097719;  // line rate, Hz
#declare TAU = 7.960125649695359e-05;  // exposure, s
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
// film: 528 x 4 samples spanning y/z in [-0.4000744023, -0.3820016084] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -2856.061819, 7303.795999>
  right <0, 132, 0>
  up <1, 0, 0>
  aperture 46.030915 blur_samples 19 focal_point <0, -3269.07564, 8359.9947> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 21370.752
  pigment { function { max(0.002, min(0.98, 0.137582 * (1 + 0.172083 * ((y / 21370.752) - -0.3910380054) / 0.009036396966 + 0.109286 * sin(19.71646 * ((y / 21370.752) - -0.3910380054) / 0.009036396966 + 0.614657)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -3935.856389, 9958.444482> + 298753 * <-0.3153756619, 0.5528370434, -0.7713036985> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, -3935.856389, 9958.444482>;  // mm
#declare V_0 = <1010.179355, -341.3541955, 324.8796743>;  // mm/s
#declare TC_0 = 0.05986201062033103;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.8424291295, 0.8237084822, 0.7675465402>] [0.5 rgb <0.8424291295, 0.8237084822, 0.7675465402>] [0.5 rgb <0.7020242746, 0.07488258929, 0.05616194197>] [1.0 rgb <0.7020242746, 0.07488258929, 0.05616194197>] } }
  finish { ambient 0.2119 diffuse 0.7881 phong 0.5437 phong_size 40 } }
  no_shadow
  rotate <262.2533635, 124.9459394, 328.2648441>
  transform { Axis_Rotate_Trans(<0.1859686635, 0.7478131878, -0.6373312265>, 137.82484 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
