// validation scene pv4039 (seed 4039)
#version 3.7;
#declare NS = 1;
#declare NLT = 87;
#declare LINES = array[87] { 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111 };
#declare LR = 8547.120677973699;  // line rate, Hz
#declare TAU = 1.5383482356284118e-05;  // exposure, s
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
// film: 716 x 4 samples spanning y/z in [-0.1201390469, 0.09261943145] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -11.55717232, 839.9225157>
  right <0, 178.7006364, 0>
  up <1, 0, 0>
  aperture 25.726362 blur_samples 19 focal_point <0, -28.41666641, 2065.1936> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 10228.334
  pigment { function { max(0.002, min(0.98, 0.087681 * (1 + -0.158035 * ((y / 10228.334) - -0.01375980772) / 0.1063792392 + 0 * sin(20.202655 * ((y / 10228.334) - -0.01375980772) / 0.1063792392 + 2.37307)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 242.0482486, 2777.716286> + 83331.5 * <0.469674953, -0.4029862459, -0.7854982649> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, 242.0482486, 2777.716286>;  // mm
#declare V_0 = <22830.76738, 1002.762769, -9699.284298>;  // mm/s
#declare TC_0 = 0.00795589562403617;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.8046422443, 0.8046422443, 0.8046422443>] [0.925 rgb <0.8046422443, 0.8046422443, 0.8046422443>] [0.935 rgb <0.04373055675, 0.04373055675, 0.04373055675>] [1.0 rgb <0.04373055675, 0.04373055675, 0.04373055675>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.5313 diffuse 0.4687 phong 0.5492 phong_size 40 } }
  no_shadow
  rotate <347.2411124, 231.4760495, 97.06012002>
  transform { Axis_Rotate_Trans(<-0.1384971756, 0.2411199448, -0.9605621815>, 8842.1187 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
