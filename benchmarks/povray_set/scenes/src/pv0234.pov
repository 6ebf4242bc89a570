// validation scene pv0234 (seed 234)
#version 3.7;
#declare NS = 1;
#declare NLT = 31;
#declare LINES = array[31] { 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38 };
#declare LR = 527.7146344921933;  // line rate, Hz
#declare TAU = 7.714285326034664e-05;  // exposure, s
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
// film: 568 x 4 samples spanning y/z in [-0.1963479189, -0.09262601726] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -197.8092297, 1369.045474>
  right <0, 142, 0>
  up <1, 0, 0>
  aperture 84.821705 blur_samples 19 focal_point <0, -1276.625892, 8835.5781> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 22290.581
  pigment { function { max(0.002, min(0.98, 0.0219343 * (1 + -0.099503 * ((y / 22290.581) - -0.1444869681) / 0.05186095082 + 0 * sin(16.283856 * ((y / 22290.581) - -0.1444869681) / 0.05186095082 + 2.32483)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -763.3835025, 5844.76727> + 175343 * <-0.2231758834, -0.4945100782, -0.8400311349> color rgb FL }
light_source { <0, -763.3835025, 5844.76727> + 175343 * <-0.9848065449, -0.1162348267, 0.1290175731> color rgb FL * 0.5196 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, -763.3835025, 5844.76727>;  // mm
#declare V_0 = <-4289.680908, 5387.987014, 346.5308694>;  // mm/s
#declare TC_0 = 0.04358416177359252;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.6649276352, 0.6649276352, 0.6649276352>] [0.925 rgb <0.6649276352, 0.6649276352, 0.6649276352>] [0.935 rgb <0.03613737148, 0.03613737148, 0.03613737148>] [1.0 rgb <0.03613737148, 0.03613737148, 0.03613737148>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.2073 diffuse 0.7927 phong 0.5417 phong_size 40 } }
  no_shadow
  rotate <279.0620741, 98.71143311, 98.67540364>
  transform { Axis_Rotate_Trans(<-0.5797858877, -0.8089811978, -0.09694197232>, 4432.0269 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
