// validation scene pv0258 (seed 258)
#version 3.7;
#declare NS = 1;
#declare NLT = 51;
#declare LINES = array[51] { 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63 };
#declare LR = 710.8345747371112;  // line rate, Hz
#declare TAU = 8.699603400306317e-05;  // exposure, s
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
// film: 2720 x 4 samples spanning y/z in [0.1858256344, 0.2278283101] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 837.1034617, 4047.361196>
  right <0, 170, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 30997.04
  pigment { function { max(0.002, min(0.98, 0.0323534 * (1 + 0.201459 * ((y / 30997.04) - 0.2068269722) / 0.02100133788 + 0.198943 * sin(14.710535 * ((y / 30997.04) - 0.2068269722) / 0.02100133788 + 1.68924)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 1160.210524, 5632.465899> + 168974 * <0.4402864869, 0.4952041849, -0.748946343> color rgb FL }
light_source { <0, 1160.210524, 5632.465899> + 168974 * <0.554948888, 0.5156123474, -0.6528212917> color rgb FL * 0.3714 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, 1160.210524, 5632.465899>;  // mm
#declare V_0 = <-1135.071908, 91.7881001, 90.35764839>;  // mm/s
#declare TC_0 = 0.05345828882064942;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.8935723151, 0.8737151525, 0.8141436648>] [0.5 rgb <0.8935723151, 0.8737151525, 0.8141436648>] [0.5 rgb <0.7446435959, 0.07942865023, 0.05957148767>] [1.0 rgb <0.7446435959, 0.07942865023, 0.05957148767>] } }
  finish { ambient 0.306 diffuse 0.694 phong 0.7106 phong_size 40 } }
  no_shadow
  rotate <49.51294811, 146.0277478, 45.71077044>
  transform { Axis_Rotate_Trans(<-0.4919347385, 0.8389443175, 0.2327501778>, 751.29983 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
