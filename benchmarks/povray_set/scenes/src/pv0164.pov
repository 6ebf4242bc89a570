// validation scene pv0164 (seed 164)
#version 3.7;
#declare NS = 3;
#declare NLT = 39;
#declare LINES = array[39] { 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48 };
#declare LR = 52.02175921899824;  // line rate, Hz
#declare TAU = 0.005109756059938689;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.110665 * sin(753.9822369 * T + 0.275791));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 2944 x 4 samples spanning y/z in [-0.05188643161, 0.07269149617] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 15.36440663, 1476.987162>
  right <0, 184, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 33705.197
  pigment { function { max(0.002, min(0.98, 0.11749 * (1 + 0.231272 * ((y / 33705.197) - 0.01040253228) / 0.06228896389 + 0.16819 * sin(14.548081 * ((y / 33705.197) - 0.01040253228) / 0.06228896389 + 6.19081)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 365.2652203, 5638.578109> + 169157 * <-0.4687940426, 0.3231669714, -0.8220676701> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, 365.2652203, 5638.578109>;  // mm
#declare V_0 = <-331.7661405, 246.6837232, -4.243626667>;  // mm/s
#declare TC_0 = 0.5574590408970495;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.7501577233, 0.7501577233, 0.7501577233>] [0.925 rgb <0.7501577233, 0.7501577233, 0.7501577233>] [0.935 rgb <0.04076944148, 0.04076944148, 0.04076944148>] [1.0 rgb <0.04076944148, 0.04076944148, 0.04076944148>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.5889 diffuse 0.4111 phong 0.6546 phong_size 40 } }
  no_shadow
  rotate <126.6127889, 152.6784385, 170.6812056>
  transform { Axis_Rotate_Trans(<0.6504296352, 0.4121009081, -0.6380549594>, 138.72528 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
