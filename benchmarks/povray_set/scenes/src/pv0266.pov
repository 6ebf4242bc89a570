// validation scene pv0266 (seed 266)
#version 3.7;
#declare NS = 2;
#declare NLT = 33;
#declare LINES = array[33] { 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39 };
#declare LR = 3670.546217283027;  // line rate, Hz
#declare TAU = 0.00014585170463270143;  // exposure, s
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
// film: 1648 x 4 samples spanning y/z in [-0.03939390191, 0.03529875372] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -2.823572547, 1378.984307>
  right <0, 103, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 72204.954
  pigment { function { max(0.002, min(0.98, 0.0122075 * (1 + 0.173162 * ((y / 72204.954) - -0.002047574096) / 0.03734632782 + 0.127536 * sin(11.75715 * ((y / 72204.954) - -0.002047574096) / 0.03734632782 + 5.45756)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -153.4998001, 14127.93724> + 423838 * <0.4283034595, 0.5024437207, -0.7510702058> color rgb FL }
light_source { <0, -153.4998001, 14127.93724> + 423838 * <-0.4103279475, 0.8160969152, 0.4069604409> color rgb FL * 0.2996 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, -153.4998001, 14127.93724>;  // mm
#declare V_0 = <-29970.54566, -1471.29295, 442.5867672>;  // mm/s
#declare TC_0 = 0.0062660973703866935;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.729317554, 0.729317554, 0.729317554>] [0.925 rgb <0.729317554, 0.729317554, 0.729317554>] [0.935 rgb <0.03963682358, 0.03963682358, 0.03963682358>] [1.0 rgb <0.03963682358, 0.03963682358, 0.03963682358>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.383 diffuse 0.617 } }
  no_shadow
  rotate <71.17284308, 311.4145275, 134.6120586>
  transform { Axis_Rotate_Trans(<0.6732101593, 0.08753468754, -0.7342518368>, 10856.525 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
