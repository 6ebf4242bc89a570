// validation scene pv0007 (seed 7)
#version 3.7;
#declare NS = 1;
#declare NLT = 29;
#declare LINES = array[29] { 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34 };
#declare LR = 403.77231963020654;  // line rate, Hz
#declare TAU = 0.00015091059673571868;  // exposure, s
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
// film: 456 x 4 samples spanning y/z in [-0.04595635889, 0.04958250091] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 2.163413876, 1193.231741>
  right <0, 114, 0>
  up <1, 0, 0>
  aperture 75.90304 blur_samples 19 focal_point <0, 7.847064009, 4328.0511> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 34329.362
  pigment { function { max(0.002, min(0.98, 0.527666 * (1 + -0.00455149 * ((y / 34329.362) - 0.001813071009) / 0.0477694299 + 0.0782834 * sin(24.739477 * ((y / 34329.362) - 0.001813071009) / 0.0477694299 + 2.28682)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -99.10167461, 6596.133956> + 197884 * <-0.614848868, 0.239207893, -0.7514921513> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, -99.10167461, 6596.133956>;  // mm
#declare V_0 = <3785.769776, -539.2511907, -1595.424041>;  // mm/s
#declare TC_0 = 0.049532865497855155;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.1274553603, 0.1274553603, 0.1274553603>] [0.925 rgb <0.1274553603, 0.1274553603, 0.1274553603>] [0.935 rgb <0.006926921756, 0.006926921756, 0.006926921756>] [1.0 rgb <0.006926921756, 0.006926921756, 0.006926921756>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.4274 diffuse 0.5726 phong 0.7301 phong_size 40 } }
  no_shadow
  rotate <190.1429247, 258.488708, 189.0186353>
  transform { Axis_Rotate_Trans(<-0.4687481674, 0.03030370914, -0.8828118943>, 2220.4235 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
