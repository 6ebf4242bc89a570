// validation scene pv0240 (seed 240)
#version 3.7;
#declare NS = 1;
#declare NLT = 59;
#declare LINES = array[59] { 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74 };
#declare LR = 139.69872112879727;  // line rate, Hz
#declare TAU = 0.002068302725516583;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.318844 * sin(753.9822369 * T + 1.75843));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 2752 x 4 samples spanning y/z in [-0.2771608707, -0.202468255] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -552.2380549, 2302.771142>
  right <0, 172, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 65516.66
  pigment { function { max(0.002, min(0.98, 0.0108711 * (1 + -0.15434 * ((y / 65516.66) - -0.2398145629) / 0.03734630785 + 0.159325 * sin(23.263229 * ((y / 65516.66) - -0.2398145629) / 0.03734630785 + 4.1142)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -2753.035899, 11456.62002> + 343699 * <0.5164087053, -0.6316974811, -0.5781698206> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, -2753.035899, 11456.62002>;  // mm
#declare V_0 = <-570.0949079, 35.2184664, 49.63039639>;  // mm/s
#declare TC_0 = 0.3221217748909211;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.7902570192, 0.7902570192, 0.7902570192>] [0.925 rgb <0.7902570192, 0.7902570192, 0.7902570192>] [0.935 rgb <0.04294875105, 0.04294875105, 0.04294875105>] [1.0 rgb <0.04294875105, 0.04294875105, 0.04294875105>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.287 diffuse 0.713 } }
  no_shadow
  rotate <43.48224791, 126.0260006, 248.336538>
  transform { Axis_Rotate_Trans(<-0.02428272727, 0.6730171952, 0.7392281137>, 202.2938 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
