// validation scene pv0274 (seed 274)
#version 3.7;
#declare NS = 1;
#declare NLT = 127;
#declare LINES = array[127] { 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162 };
#declare LR = 104.70696875034393;  // line rate, Hz
#declare TAU = 0.0006694484513134058;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.0503164 * sin(753.9822369 * T + 0.814215));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 2192 x 4 samples spanning y/z in [-0.05012774015, 0.06150463779] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 6.974638797, 1226.105573>
  right <0, 136.8730807, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 39578.989
  pigment { function { max(0.002, min(0.98, 0.617803 * (1 + -0.121964 * ((y / 39578.989) - 0.005688448818) / 0.05581618897 + 0.0525139 * sin(9.3398693 * ((y / 39578.989) - 0.005688448818) / 0.05581618897 + 1.38304)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 328.0034164, 8374.649928> + 251239 * <0.7224815867, -0.5954973801, -0.3512879549> color rgb FL }
light_source { <0, 328.0034164, 8374.649928> + 251239 * <-0.0647483968, 0.7115955853, -0.699599434> color rgb FL * 0.214 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, 328.0034164, 8374.649928>;  // mm
#declare V_0 = <193.4432484, -100.5716663, 3.921389201>;  // mm/s
#declare TC_0 = 0.9454958077914447;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.1226212616, 0.1226212616, 0.1226212616>] [0.925 rgb <0.1226212616, 0.1226212616, 0.1226212616>] [0.935 rgb <0.006664199, 0.006664199, 0.006664199>] [1.0 rgb <0.006664199, 0.006664199, 0.006664199>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.5067 diffuse 0.4933 } }
  no_shadow
  rotate <229.1762246, 247.6001344, 44.00203162>
  transform { Axis_Rotate_Trans(<0.6994822992, 0.1174503272, 0.7049325739>, 0 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
