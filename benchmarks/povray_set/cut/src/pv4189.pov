// validation scene pv4189 (seed 4189)
#version 3.7;
#declare NS = 2;
#declare NLT = 91;
#declare LINES = array[91] { 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115 };
#declare LR = 595.9578036733872;  // line rate, Hz
#declare TAU = 0.0007019599252471146;  // exposure, s
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
// film: 3136 x 4 samples spanning y/z in [-0.042947458, 0.03804512457] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -5.931761423, 2419.974691>
  right <0, 196, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 38406.82
  pigment { function { max(0.002, min(0.98, 0.0840983 * (1 + -0.375728 * ((y / 38406.82) - -0.002451166719) / 0.04049629128 + 0.0694859 * sin(12.180237 * ((y / 38406.82) - -0.002451166719) / 0.04049629128 + 5.07883)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -360.4829175, 9027.034639> + 270811 * <0.5625600402, 0.6221988593, -0.5444215101> color rgb FL }
light_source { <0, -360.4829175, 9027.034639> + 270811 * <-0.4109565097, -0.8250511634, 0.3878212539> color rgb FL * 0.2282 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, -360.4829175, 9027.034639>;  // mm
#declare V_0 = <1550.245569, 222.4695305, 53.70385651>;  // mm/s
#declare TC_0 = 0.11745798036124598;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.7270101636, 0.7270101636, 0.7270101636>] [0.925 rgb <0.7270101636, 0.7270101636, 0.7270101636>] [0.935 rgb <0.03951142193, 0.03951142193, 0.03951142193>] [1.0 rgb <0.03951142193, 0.03951142193, 0.03951142193>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.3877 diffuse 0.6123 phong 0.297 phong_size 40 } }
  no_shadow
  rotate <99.37288593, 108.5815047, 38.91170551>
  transform { Axis_Rotate_Trans(<0.7561771579, -0.4844759446, -0.439862666>, 362.88211 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
