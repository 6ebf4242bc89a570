// validation scene pv0225 (seed 225)
#version 3.7;
#declare NS = 1;
#declare NLT = 43;
#declare LINES = array[43] { 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53 };
#declare LR = 25.85992777624748;  // line rate, Hz
#declare TAU = 0.0040783341200141465;  // exposure, s
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
// film: 1840 x 4 samples spanning y/z in [-0.3263163653, -0.2853578806] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -901.6642887, 2948.184576>
  right <0, 120.7531728, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 66827.117
  pigment { function { max(0.002, min(0.98, 0.021606 * (1 + -0.0376883 * ((y / 66827.117) - -0.3058371229) / 0.02047924233 + 0.00664073 * sin(25.09985 * ((y / 66827.117) - -0.3058371229) / 0.02047924233 + 4.67825)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -3987.85878, 13017.57868> + 390527 * <-0.2997819623, -0.1262290744, -0.9456199003> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, -3987.85878, 13017.57868>;  // mm
#declare V_0 = <-148.2501755, 45.00559684, 76.54285349>;  // mm/s
#declare TC_0 = 1.2374357839232721;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.8840300444, 0.8840300444, 0.8840300444>] [0.925 rgb <0.8840300444, 0.8840300444, 0.8840300444>] [0.935 rgb <0.04804511111, 0.04804511111, 0.04804511111>] [1.0 rgb <0.04804511111, 0.04804511111, 0.04804511111>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.3737 diffuse 0.6263 } }
  no_shadow
  rotate <359.5739639, 343.7299837, 246.7163504>
  transform { Axis_Rotate_Trans(<-0.03310993108, 0.05571095926, -0.9978978011>, 81.99958 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
