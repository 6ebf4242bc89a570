// validation scene pv0242 (seed 242)
#version 3.7;
#declare NS = 1;
#declare NLT = 60;
#declare LINES = array[60] { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59 };
#declare LR = 2824.20077206643;  // line rate, Hz
#declare TAU = 1.1144112533920368e-05;  // exposure, s
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
// film: 2928 x 4 samples spanning y/z in [0.2525589566, 0.4517316797] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 296.803091, 842.842644>
  right <0, 167.8712645, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 17055.829
  pigment { function { max(0.002, min(0.98, 0.0166694 * (1 + -0.327481 * ((y / 17055.829) - 0.3521453182) / 0.09958636155 + 0.0676739 * sin(9.1883383 * ((y / 17055.829) - 0.3521453182) / 0.09958636155 + 5.83789)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 1482.857784, 5048.155533> + 151445 * <0.3608456195, -0.5172209315, -0.7760624633> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, 1482.857784, 5048.155533>;  // mm
#declare V_0 = <7285.878198, 1599.252349, -135.9730759>;  // mm/s
#declare TC_0 = 0.004957154653617769;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.8070886923, 0.8070886923, 0.8070886923>] [0.925 rgb <0.8070886923, 0.8070886923, 0.8070886923>] [0.935 rgb <0.04386351588, 0.04386351588, 0.04386351588>] [1.0 rgb <0.04386351588, 0.04386351588, 0.04386351588>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.5463 diffuse 0.4537 phong 0.616 phong_size 40 } }
  no_shadow
  rotate <286.3570202, 93.97391082, 165.5794877>
  transform { Axis_Rotate_Trans(<-0.7034044987, 0.5475437911, -0.4532305241>, 3772.1162 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
