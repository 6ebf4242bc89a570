// validation scene pv0045 (seed 45)
#version 3.7;
#declare NS = 1;
#declare NLT = 53;
#declare LINES = array[53] { 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66 };
#declare LR = 97.87740010542697;  // line rate, Hz
#declare TAU = 0.0005555647210830269;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.0660742 * sin(628.3185307 * T + 3.15233));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 2736 x 4 samples spanning y/z in [-0.07273763685, 0.06167907508] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -7.02799805, 1271.05101>
  right <0, 170.8504975, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 32258.676
  pigment { function { max(0.002, min(0.98, 0.836491 * (1 + -0.309687 * ((y / 32258.676) - -0.005529280882) / 0.06720835596 + 0 * sin(24.493286 * ((y / 32258.676) - -0.005529280882) / 0.06720835596 + 5.51099)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -786.990248, 11593.0057> + 347790 * <-0.2389237752, 0.03481338405, -0.9704140652> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, -786.990248, 11593.0057>;  // mm
#declare V_0 = <451.690139, 47.131587, 9.740910038>;  // mm/s
#declare TC_0 = 0.4086745250375948;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.106305748, 0.106305748, 0.106305748>] [0.925 rgb <0.106305748, 0.106305748, 0.106305748>] [0.935 rgb <0.005777486303, 0.005777486303, 0.005777486303>] [1.0 rgb <0.005777486303, 0.005777486303, 0.005777486303>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.4607 diffuse 0.5393 phong 0.2265 phong_size 40 } }
  no_shadow
  rotate <222.9074814, 310.6092279, 34.54197979>
  transform { Axis_Rotate_Trans(<0.06042925839, 0.3236953647, 0.9442296413>, 203.36509 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
