// validation scene pv3633 (seed 3633)
#version 3.7;
#declare NS = 1;
#declare NLT = 119;
#declare LINES = array[119] { 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168 };
#declare LR = 35587.96904218596;  // line rate, Hz
#declare TAU = 6.29944934466775e-06;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.199102 * sin(628.3185307 * T + 3.87667));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 1472 x 4 samples spanning y/z in [-0.02072245938, 0.01610311989] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -5.770163584, 2498.263485>
  right <0, 92, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 10388.872
  pigment { function { max(0.002, min(0.98, 0.610234 * (1 + 0.258723 * ((y / 10388.872) - -0.002309669745) / 0.01841278964 + 0 * sin(5.9922746 * ((y / 10388.872) - -0.002309669745) / 0.01841278964 + 0.521053)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -17.26148548, 3407.255739> + 102218 * <-0.3786943422, -0.543216953, -0.7493369984> color rgb FL }
light_source { <0, -17.26148548, 3407.255739> + 102218 * <-0.1135021547, -0.05980097269, -0.9917364088> color rgb FL * 0.3553 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, -17.26148548, 3407.255739>;  // mm
#declare V_0 = <-15544.55755, -63.6589725, 971.0176743>;  // mm/s
#declare TC_0 = 0.0038496155776015276;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.1367080042, 0.1336700486, 0.1245561816>] [0.5 rgb <0.1367080042, 0.1336700486, 0.1245561816>] [0.5 rgb <0.1139233369, 0.0121518226, 0.009113866948>] [1.0 rgb <0.1139233369, 0.0121518226, 0.009113866948>] } }
  finish { ambient 0.5684 diffuse 0.4316 phong 0.1 phong_size 40 } }
  no_shadow
  rotate <236.3570671, 256.8250723, 110.9689782>
  transform { Axis_Rotate_Trans(<0.1717850217, -0.8263416939, 0.53632948>, 6098.078 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
