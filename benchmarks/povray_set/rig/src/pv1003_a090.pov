// validation scene pv1003_a090 (seed 1003)
#version 3.7;
#declare NS = 1;
#declare NLT = 131;
#declare LINES = array[131] { 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168 };
#declare LR = 20423.128074618387;  // line rate, Hz
#declare TAU = 6.9429277111770946e-06;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.176541 * sin(628.3185307 * T + 1.36394));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 1280 x 4 samples spanning y/z in [-0.03634429617, 0.02535860181] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -7.121671571, 1296.535537>
  right <0, 80, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 54442.056
  pigment { function { max(0.002, min(0.98, 0.0389932 * (1 + 0.0611742 * ((y / 54442.056) - -0.00549284718) / 0.03085144899 + 0 * sin(21.33707 * ((y / 54442.056) - -0.00549284718) / 0.03085144899 + 1.73393)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -268.5326888, 13956.52327> + 418696 * <-0.317787175, 0.9280433491, -0.1942854953> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, -268.5326888, 13956.52327>;  // mm
#declare V_0 = <-13452.38208, -3643.572081, 627.2986483>;  // mm/s
#declare TC_0 = 0.00504330186951171;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.8187991399, 0.8006036034, 0.7460169941>] [0.5 rgb <0.8187991399, 0.8006036034, 0.7460169941>] [0.5 rgb <0.6823326166, 0.07278214577, 0.05458660933>] [1.0 rgb <0.6823326166, 0.07278214577, 0.05458660933>] } }
  finish { ambient 0.24 diffuse 0.76 phong 0.1 phong_size 40 } }
  no_shadow
  rotate <152.7234444, 219.2206964, 240.4543181>
  transform { Axis_Rotate_Trans(<-0.8755603063, 0.01415346233, 0.4829014699>, 203.08599 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
