// validation scene pv0189 (seed 189)
#version 3.7;
#declare NS = 1;
#declare NLT = 24;
#declare LINES = array[24] { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23 };
#declare LR = 579.7182757041317;  // line rate, Hz
#declare TAU = 0.0001390575961071422;  // exposure, s
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
// film: 2704 x 4 samples spanning y/z in [0.06366158889, 0.1994448061] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 163.7351864, 1244.63099>
  right <0, 169, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 39182.116
  pigment { function { max(0.002, min(0.98, 0.0160425 * (1 + -0.0272273 * ((y / 39182.116) - 0.1315531975) / 0.06789160859 + 0.0871099 * sin(24.70441 * ((y / 39182.116) - 0.1315531975) / 0.06789160859 + 2.51447)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 817.6713251, 6752.388196> + 202572 * <-0.764456884, -0.2269737259, -0.6033975475> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, 817.6713251, 6752.388196>;  // mm
#declare V_0 = <4672.879405, 6890.509803, 430.7717208>;  // mm/s
#declare TC_0 = 0.01207483064338058;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.8159088172, 0.8159088172, 0.8159088172>] [0.925 rgb <0.8159088172, 0.8159088172, 0.8159088172>] [0.935 rgb <0.0443428705, 0.0443428705, 0.0443428705>] [1.0 rgb <0.0443428705, 0.0443428705, 0.0443428705>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.5147 diffuse 0.4853 } }
  no_shadow
  rotate <271.883242, 194.8422081, 273.6341192>
  transform { Axis_Rotate_Trans(<-0.8042277292, -0.1930106617, 0.5621073243>, 2658.3043 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
