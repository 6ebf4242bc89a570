// validation scene pv3523 (seed 3523)
#version 3.7;
#declare NS = 1;
#declare NLT = 101;
#declare LINES = array[101] { 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156 };
#declare LR = 4244.982352581523;  // line rate, Hz
#declare TAU = 3.9841173687809666e-05;  // exposure, s
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
// film: 2336 x 4 samples spanning y/z in [0.05045425661, 0.1786125418] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 130.4783086, 1139.216242>
  right <0, 146, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 2931.1879
  pigment { function { max(0.002, min(0.98, 0.0176685 * (1 + -0.109297 * ((y / 2931.1879) - 0.1145333992) / 0.06407914261 + 0 * sin(10.614702 * ((y / 2931.1879) - 0.1145333992) / 0.06407914261 + 5.87433)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 153.048855, 1343.412167> + 40302.4 * <-0.5921377702, 0.6301527247, -0.502275228> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, 153.048855, 1343.412167>;  // mm
#declare V_0 = <1662.295788, -244.7594559, -12.76679286>;  // mm/s
#declare TC_0 = 0.03604255266384213;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.686271697, 0.6710212148, 0.6252697683>] [0.5 rgb <0.686271697, 0.6710212148, 0.6252697683>] [0.5 rgb <0.5718930808, 0.06100192862, 0.04575144646>] [1.0 rgb <0.5718930808, 0.06100192862, 0.04575144646>] } }
  finish { ambient 0.4914 diffuse 0.5086 phong 0.1 phong_size 40 } }
  no_shadow
  rotate <107.226668, 38.36722111, 176.8115136>
  transform { Axis_Rotate_Trans(<0.6672209965, 0.6290577532, 0.3988765284>, 112.61102 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
