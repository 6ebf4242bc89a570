// validation scene pv4208 (seed 4208)
#version 3.7;
#declare NS = 1;
#declare NLT = 60;
#declare LINES = array[60] { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59 };
#declare LR = 6790.373808209813;  // line rate, Hz
#declare TAU = 6.948455218679186e-05;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.271138 * sin(628.3185307 * T + 0.598819));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 2144 x 4 samples spanning y/z in [-0.1208195164, 0.04272600006] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -31.99271805, 819.3437697>
  right <0, 134, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 36706.47
  pigment { function { max(0.002, min(0.98, 0.0468932 * (1 + -0.348545 * ((y / 36706.47) - -0.03904675819) / 0.08177275825 + 0.214737 * sin(19.155482 * ((y / 36706.47) - -0.03904675819) / 0.08177275825 + 4.68368)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 180.4237865, 8331.382272> + 249941 * <0.339416147, -0.3694193479, -0.8650583937> color rgb FL }
light_source { <0, 180.4237865, 8331.382272> + 249941 * <-0.6771646617, 0.3629829102, -0.640071424> color rgb FL * 0.5367 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, 180.4237865, 8331.382272>;  // mm
#declare V_0 = <-16666.15024, -10536.51715, -2491.307294>;  // mm/s
#declare TC_0 = 0.0014726729753684002;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.7479066555, 0.7479066555, 0.7479066555>] [0.925 rgb <0.7479066555, 0.7479066555, 0.7479066555>] [0.935 rgb <0.04064710084, 0.04064710084, 0.04064710084>] [1.0 rgb <0.04064710084, 0.04064710084, 0.04064710084>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.2409 diffuse 0.7591 } }
  no_shadow
  rotate <156.2472317, 21.19639596, 167.3578574>
  transform { Axis_Rotate_Trans(<0.1572068132, 0.9864894022, 0.04609422017>, 11478.864 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
