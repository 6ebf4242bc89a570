// validation scene pv3771 (seed 3771)
#version 3.7;
#declare NS = 1;
#declare NLT = 125;
#declare LINES = array[125] { 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160 };
#declare LR = 178.04786998809163;  // line rate, Hz
#declare TAU = 0.00048109794169387874;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.0634259 * sin(628.3185307 * T + 0.0659613));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 392 x 4 samples spanning y/z in [-0.04640997172, 0.04279958617] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -1.983071051, 1098.536999>
  right <0, 98, 0>
  up <1, 0, 0>
  aperture 46.068383 blur_samples 19 focal_point <0, -8.109721357, 4492.4406> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 17921.013
  pigment { function { max(0.002, min(0.98, 0.0114528 * (1 + 0.216123 * ((y / 17921.013) - -0.001805192773) / 0.04460477895 + 0 * sin(5.9626569 * ((y / 17921.013) - -0.001805192773) / 0.04460477895 + 0.661206)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 150.7887032, 3080.22799> + 92406.8 * <0.2142101122, 0.3049191245, -0.9279754066> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, 150.7887032, 3080.22799>;  // mm
#declare V_0 = <325.9785803, 25.08328151, 88.94705356>;  // mm/s
#declare TC_0 = 0.5504137735910827;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.8754463325, 0.8754463325, 0.8754463325>] [0.925 rgb <0.8754463325, 0.8754463325, 0.8754463325>] [0.935 rgb <0.04757860503, 0.04757860503, 0.04757860503>] [1.0 rgb <0.04757860503, 0.04757860503, 0.04757860503>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.467 diffuse 0.533 } }
  no_shadow
  rotate <192.4100263, 107.6920094, 267.8351032>
  transform { Axis_Rotate_Trans(<-0.2865803721, -0.4065863005, 0.867501741>, 0 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
