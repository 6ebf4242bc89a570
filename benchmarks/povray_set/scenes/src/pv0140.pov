// validation scene pv0140 (seed 140)
#version 3.7;
#declare NS = 1;
#declare NLT = 88;
#declare LINES = array[88] { 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139 };
#declare LR = 14030.331693967466;  // line rate, Hz
#declare TAU = 5.7366505634929435e-06;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.216621 * sin(753.9822369 * T + 5.03495));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 2800 x 4 samples spanning y/z in [-0.02640547647, 0.03165138565] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 7.906335902, 3014.286229>
  right <0, 175, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 19604.966
  pigment { function { max(0.002, min(0.98, 0.199687 * (1 + -0.303817 * ((y / 19604.966) - 0.002622954591) / 0.02902843106 + 0.0703823 * sin(9.6327287 * ((y / 19604.966) - 0.002622954591) / 0.02902843106 + 3.96601)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -45.04842779, 3730.737568> + 111922 * <0.1535392497, 0.1595112736, -0.9751829841> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, -45.04842779, 3730.737568>;  // mm
#declare V_0 = <-5888.598235, -1792.467586, 220.7864963>;  // mm/s
#declare TC_0 = 0.010120929647091298;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.7385263515, 0.7221146548, 0.6728795647>] [0.5 rgb <0.7385263515, 0.7221146548, 0.6728795647>] [0.5 rgb <0.6154386262, 0.0656467868, 0.0492350901>] [1.0 rgb <0.6154386262, 0.0656467868, 0.0492350901>] } }
  finish { ambient 0.1092 diffuse 0.8908 phong 0.1 phong_size 40 } }
  no_shadow
  rotate <352.8211431, 283.1310151, 197.4455619>
  transform { Axis_Rotate_Trans(<0.3777999409, 0.925860032, -0.007099696465>, 1957.881 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
