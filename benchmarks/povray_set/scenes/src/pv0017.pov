// validation scene pv0017 (seed 17)
#version 3.7;
#declare NS = 1;
#declare NLT = 35;
#declare LINES = array[35] { 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42 };
#declare LR = 561.8942729861524;  // line rate, Hz
#declare TAU = 0.00018253420420247994;  // exposure, s
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
// film: 332 x 4 samples spanning y/z in [-0.2588341606, -0.2333452071] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -801.3449326, 3256.312577>
  right <0, 83, 0>
  up <1, 0, 0>
  aperture 47.755782 blur_samples 19 focal_point <0, -1888.420457, 7673.7083> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 71209.91
  pigment { function { max(0.002, min(0.98, 0.0137049 * (1 + 0.232997 * ((y / 71209.91) - -0.2460896839) / 0.01274447677 + 0.0640238 * sin(6.7553605 * ((y / 71209.91) - -0.2460896839) / 0.01274447677 + 4.41869)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -3018.709365, 12126.01789> + 363781 * <0.437665283, 0.04256056049, -0.8981301124> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, -3018.709365, 12126.01789>;  // mm
#declare V_0 = <4138.205906, 194.2616087, 88.47843367>;  // mm/s
#declare TC_0 = 0.04449235595005987;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.8556168761, 0.8556168761, 0.8556168761>] [0.925 rgb <0.8556168761, 0.8556168761, 0.8556168761>] [0.935 rgb <0.04650091718, 0.04650091718, 0.04650091718>] [1.0 rgb <0.04650091718, 0.04650091718, 0.04650091718>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.5375 diffuse 0.4625 } }
  no_shadow
  rotate <300.6792792, 311.8804321, 16.7850777>
  transform { Axis_Rotate_Trans(<0.2808453019, 0.4968148769, -0.8211582639>, 1027.457 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
