// validation scene pv0087 (seed 87)
#version 3.7;
#declare NS = 1;
#declare NLT = 45;
#declare LINES = array[45] { 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55 };
#declare LR = 96.60961791162495;  // line rate, Hz
#declare TAU = 0.0008454943159847794;  // exposure, s
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
// film: 2720 x 4 samples spanning y/z in [-0.00339982157, 0.118094566] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 80.24282826, 1399.241589>
  right <0, 170, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 43226.598
  pigment { function { max(0.002, min(0.98, 0.0188745 * (1 + 0.38848 * ((y / 43226.598) - 0.05734737224) / 0.0607471938 + 0 * sin(5.8213696 * ((y / 43226.598) - 0.05734737224) / 0.0607471938 + 1.51549)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 1052.616655, 9033.833076> + 271015 * <0.6034539392, -0.0565381321, -0.7953909623> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, 1052.616655, 9033.833076>;  // mm
#declare V_0 = <-535.5208478, -386.4654071, 0.9690638092>;  // mm/s
#declare TC_0 = 0.3415808975684722;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.8154685826, 0.8154685826, 0.8154685826>] [0.925 rgb <0.8154685826, 0.8154685826, 0.8154685826>] [0.935 rgb <0.04431894471, 0.04431894471, 0.04431894471>] [1.0 rgb <0.04431894471, 0.04431894471, 0.04431894471>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.1721 diffuse 0.8279 phong 0.5599 phong_size 40 } }
  no_shadow
  rotate <172.7899872, 279.7319188, 206.4821464>
  transform { Axis_Rotate_Trans(<0.8670924833, -0.2942031946, -0.4019889372>, 0 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
