// validation scene pv3549 (seed 3549)
#version 3.7;
#declare NS = 1;
#declare NLT = 83;
#declare LINES = array[83] { 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136 };
#declare LR = 58.23157958943485;  // line rate, Hz
#declare TAU = 0.0006982327111062806;  // exposure, s
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
// film: 1760 x 4 samples spanning y/z in [-0.05694038887, 0.07069502791] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 5.927078598, 861.8297552>
  right <0, 110, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 10059.086
  pigment { function { max(0.002, min(0.98, 0.0447668 * (1 + 0.0584614 * ((y / 10059.086) - 0.006877319519) / 0.06381770839 + 0.0211238 * sin(17.20981 * ((y / 10059.086) - 0.006877319519) / 0.06381770839 + 3.36078)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 7.447718095, 2875.561448> + 86266.8 * <0.5820344465, 0.4278819957, -0.6914860091> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, 7.447718095, 2875.561448>;  // mm
#declare V_0 = <-70.87026922, -10.22214127, 15.57211786>;  // mm/s
#declare TC_0 = 2.5244034428815443;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.799870419, 0.799870419, 0.799870419>] [0.925 rgb <0.799870419, 0.799870419, 0.799870419>] [0.935 rgb <0.04347121842, 0.04347121842, 0.04347121842>] [1.0 rgb <0.04347121842, 0.04347121842, 0.04347121842>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.1309 diffuse 0.8691 } }
  no_shadow
  rotate <101.4002687, 327.3030989, 254.5756363>
  transform { Axis_Rotate_Trans(<-0.3410793318, 0.4844099449, -0.8056127448>, 64.473611 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
