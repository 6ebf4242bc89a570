// validation scene pv0253 (seed 253)
#version 3.7;
#declare NS = 1;
#declare NLT = 47;
#declare LINES = array[47] { 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58 };
#declare LR = 770.701103687226;  // line rate, Hz
#declare TAU = 0.00010427891641976828;  // exposure, s
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
// film: 1152 x 4 samples spanning y/z in [-0.02593534031, 0.0207340469] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -4.012192441, 1542.767204>
  right <0, 72, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 44266.44
  pigment { function { max(0.002, min(0.98, 0.128105 * (1 + -0.0479823 * ((y / 44266.44) - -0.002600646703) / 0.0233346936 + 0 * sin(4.9044482 * ((y / 44266.44) - -0.002600646703) / 0.0233346936 + 4.67739)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 157.8928096, 9597.779749> + 287933 * <-0.4913304273, -0.6822499547, -0.5414142688> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, 157.8928096, 9597.779749>;  // mm
#declare V_0 = <-4016.705706, -321.612551, 96.25377036>;  // mm/s
#declare TC_0 = 0.04541319563777875;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.7099894983, 0.7099894983, 0.7099894983>] [0.925 rgb <0.7099894983, 0.7099894983, 0.7099894983>] [0.935 rgb <0.03858638577, 0.03858638577, 0.03858638577>] [1.0 rgb <0.03858638577, 0.03858638577, 0.03858638577>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.5657 diffuse 0.4343 } }
  no_shadow
  rotate <308.7290072, 340.1724736, 307.8989667>
  transform { Axis_Rotate_Trans(<-0.5986248554, -0.4694734456, 0.6490323307>, 2868.3621 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
