// validation scene pv0247 (seed 247)
#version 3.7;
#declare NS = 1;
#declare NLT = 91;
#declare LINES = array[91] { 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115 };
#declare LR = 20.0;  // line rate, Hz
#declare TAU = 0.00295546961486105;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.176136 * sin(628.3185307 * T + 5.51193));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 1872 x 4 samples spanning y/z in [0.03014292056, 0.07161586457] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 143.5449103, 2821.277988>
  right <0, 117.006704, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 26683.021
  pigment { function { max(0.002, min(0.98, 0.0200332 * (1 + 0.0579746 * ((y / 26683.021) - 0.05087939256) / 0.020736472 + 0.0698608 * sin(7.0318213 * ((y / 26683.021) - 0.05087939256) / 0.020736472 + 2.17559)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 259.4195086, 8892.179685> + 266765 * <-0.5988224074, 0.308892259, -0.7389162989> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, 259.4195086, 8892.179685>;  // mm
#declare V_0 = <-51.16982891, 2.331944294, 0.8164472868>;  // mm/s
#declare TC_0 = 3.5;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.8376301031, 0.8376301031, 0.8376301031>] [0.925 rgb <0.8376301031, 0.8376301031, 0.8376301031>] [0.935 rgb <0.04552337517, 0.04552337517, 0.04552337517>] [1.0 rgb <0.04552337517, 0.04552337517, 0.04552337517>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.5937 diffuse 0.4063 } }
  no_shadow
  rotate <300.5081013, 44.42192444, 150.736086>
  transform { Axis_Rotate_Trans(<-0.6867898306, -0.2607214911, -0.6784865751>, 0 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
