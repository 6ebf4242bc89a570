// validation scene pv3924 (seed 3924)
#version 3.7;
#declare NS = 1;
#declare NLT = 163;
#declare LINES = array[163] { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162 };
#declare LR = 633.194438818391;  // line rate, Hz
#declare TAU = 0.00014051515024028768;  // exposure, s
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
// film: 332 x 4 samples spanning y/z in [-0.03206099326, 0.04554892292] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 7.21409824, 1069.711723>
  right <0, 83.02023717, 0>
  up <1, 0, 0>
  aperture 124.65858 blur_samples 19 focal_point <0, 29.97325607, 4444.4562> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 23829.594
  pigment { function { max(0.002, min(0.98, 0.155695 * (1 + -0.364781 * ((y / 23829.594) - 0.006743964831) / 0.03880495809 + 0.225769 * sin(21.204443 * ((y / 23829.594) - 0.006743964831) / 0.03880495809 + 0.535102)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 82.19566277, 5737.764347> + 172133 * <-0.1327481755, -0.3091329714, -0.9417084092> color rgb FL }
light_source { <0, 82.19566277, 5737.764347> + 172133 * <0.3682362681, -0.7389159345, 0.5642741289> color rgb FL * 0.6389 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, 82.19566277, 5737.764347>;  // mm
#declare V_0 = <-566.8284161, 87.27718879, 12.31244232>;  // mm/s
#declare TC_0 = 0.05527528015772497;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.8146588975, 0.8146588975, 0.8146588975>] [0.925 rgb <0.8146588975, 0.8146588975, 0.8146588975>] [0.935 rgb <0.04427494008, 0.04427494008, 0.04427494008>] [1.0 rgb <0.04427494008, 0.04427494008, 0.04427494008>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.2823 diffuse 0.7177 phong 0.7211 phong_size 40 } }
  no_shadow
  rotate <271.0056928, 20.63239161, 131.6582374>
  transform { Axis_Rotate_Trans(<-0.5082861858, -0.7320006794, -0.4536740666>, 512.70476 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
