// validation scene pv0298 (seed 298)
#version 3.7;
#declare NS = 1;
#declare NLT = 109;
#declare LINES = array[109] { 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139 };
#declare LR = 1137.1721490250302;  // line rate, Hz
#declare TAU = 0.00029898017029395446;  // exposure, s
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
// film: 1392 x 4 samples spanning y/z in [0.02538756283, 0.04917529756] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 136.2053907, 3653.437917>
  right <0, 86.90701203, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 43098.251
  pigment { function { max(0.002, min(0.98, 0.0299186 * (1 + -0.361555 * ((y / 43098.251) - 0.0372814302) / 0.01189386736 + 0.0582427 * sin(4.4537455 * ((y / 43098.251) - 0.0372814302) / 0.01189386736 + 4.34514)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 317.7968761, 7367.012156> + 221010 * <-0.5935452604, -0.3064241583, -0.7441829473> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, 317.7968761, 7367.012156>;  // mm
#declare V_0 = <745.9050594, -67.86665819, 18.81745844>;  // mm/s
#declare TC_0 = 0.07474681830088425;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.8090659466, 0.8090659466, 0.7914775564>] [0.44 rgb <0.8090659466, 0.8090659466, 0.7914775564>] [0.46 rgb <0.615593655, 0.7475065811, 0.1319129261>] [1.00 rgb <0.615593655, 0.7475065811, 0.1319129261>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.2459 diffuse 0.7541 } }
  no_shadow
  rotate <41.31644076, 7.885653938, 205.2346893>
  transform { Axis_Rotate_Trans(<0.5176740975, -0.009638123934, -0.855523603>, 415.43436 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
