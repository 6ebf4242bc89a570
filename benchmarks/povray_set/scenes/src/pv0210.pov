// validation scene pv0210 (seed 210)
#version 3.7;
#declare NS = 1;
#declare NLT = 109;
#declare LINES = array[109] { 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138 };
#declare LR = 235.64591508598286;  // line rate, Hz
#declare TAU = 0.0006128897826631997;  // exposure, s
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
// film: 428 x 4 samples spanning y/z in [-0.04298137925, 0.03743377334] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -3.69017342, 1330.366099>
  right <0, 106.9815928, 0>
  up <1, 0, 0>
  aperture 88.317993 blur_samples 19 focal_point <0, -18.99965507, 6849.6773> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 30516.038
  pigment { function { max(0.002, min(0.98, 0.0158133 * (1 + 0.363964 * ((y / 30516.038) - -0.002773802958) / 0.04020757629 + 0.245762 * sin(4.3677052 * ((y / 30516.038) - -0.002773802958) / 0.04020757629 + 1.4175)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -331.1590793, 11032.40834> + 330972 * <0.1735681473, 0.6327759385, -0.7546315061> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, -331.1590793, 11032.40834>;  // mm
#declare V_0 = <170.4129944, 92.65906724, 10.8974408>;  // mm/s
#declare TC_0 = 0.3564670321968023;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.82429623, 0.82429623, 0.8063767468>] [0.44 rgb <0.82429623, 0.82429623, 0.8063767468>] [0.46 rgb <0.6271819142, 0.7615780386, 0.1343961245>] [1.00 rgb <0.6271819142, 0.7615780386, 0.1343961245>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.1879 diffuse 0.8121 } }
  no_shadow
  rotate <175.4899995, 325.4254021, 212.4152174>
  transform { Axis_Rotate_Trans(<0.6737627163, 0.7266061695, 0.1344889457>, 124.41073 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
