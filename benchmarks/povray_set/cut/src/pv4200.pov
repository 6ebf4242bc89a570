// validation scene pv4200 (seed 4200)
#version 3.7;
#declare NS = 1;
#declare NLT = 105;
#declare LINES = array[105] { 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134 };
#declare LR = 29.86014050552964;  // line rate, Hz
#declare TAU = 0.004576118940126072;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.285019 * sin(628.3185307 * T + 1.56203));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 2960 x 4 samples spanning y/z in [0.20857651, 0.3342652411] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 416.868914, 1535.876388>
  right <0, 193.0423544, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 21201.421
  pigment { function { max(0.002, min(0.98, 0.194406 * (1 + 0.170255 * ((y / 21201.421) - 0.2714208755) / 0.06284436556 + 0 * sin(19.012453 * ((y / 21201.421) - 0.2714208755) / 0.06284436556 + 3.57354)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 1595.383539, 4883.783883> + 146514 * <0.2924945259, -0.1344450925, -0.946768963> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, 1595.383539, 4883.783883>;  // mm
#declare V_0 = <65.82616909, -5.308791484, -11.86030212>;  // mm/s
#declare TC_0 = 2.7461357720274244;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.8027782321, 0.8027782321, 0.8027782321>] [0.925 rgb <0.8027782321, 0.8027782321, 0.8027782321>] [0.935 rgb <0.04362925175, 0.04362925175, 0.04362925175>] [1.0 rgb <0.04362925175, 0.04362925175, 0.04362925175>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.1624 diffuse 0.8376 } }
  no_shadow
  rotate <63.03656002, 332.4882829, 232.5219279>
  transform { Axis_Rotate_Trans(<0.3552288282, -0.3751147444, -0.8562134127>, 12.547956 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
