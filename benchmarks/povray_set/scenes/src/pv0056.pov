// validation scene pv0056 (seed 56)
#version 3.7;
#declare NS = 1;
#declare NLT = 101;
#declare LINES = array[101] { 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128 };
#declare LR = 334.55513839039156;  // line rate, Hz
#declare TAU = 0.00026443019190177373;  // exposure, s
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
// film: 1648 x 4 samples spanning y/z in [-0.2432747624, -0.1799672263] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -344.302808, 1626.9785>
  right <0, 103, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 43122.748
  pigment { function { max(0.002, min(0.98, 0.694986 * (1 + 0.278188 * ((y / 43122.748) - -0.2116209944) / 0.03165376801 + 0.0481213 * sin(22.449926 * ((y / 43122.748) - -0.2116209944) / 0.03165376801 + 4.923)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -2552.348541, 12717.61037> + 381528 * <0.6453359008, 0.1863803962, -0.7408130149> color rgb FL }
light_source { <0, -2552.348541, 12717.61037> + 381528 * <0.205026079, -0.7319616939, -0.6497664084> color rgb FL * 0.4431 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, -2552.348541, 12717.61037>;  // mm
#declare V_0 = <-278.3757697, 9.854103059, -121.6763063>;  // mm/s
#declare TC_0 = 0.23314542522130385;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.1392117104, 0.1361181168, 0.1268373361>] [0.5 rgb <0.1392117104, 0.1361181168, 0.1268373361>] [0.5 rgb <0.1160097587, 0.01237437426, 0.009280780692>] [1.0 rgb <0.1160097587, 0.01237437426, 0.009280780692>] } }
  finish { ambient 0.2765 diffuse 0.7235 phong 0.1 phong_size 40 } }
  no_shadow
  rotate <27.7687504, 36.6000097, 63.86343814>
  transform { Axis_Rotate_Trans(<-0.7301647034, 0.4564743882, -0.5084197467>, 3.2205285 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
