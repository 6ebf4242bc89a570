// validation scene pv3461 (seed 3461)
#version 3.7;
#declare NS = 1;
#declare NLT = 84;
#declare LINES = array[84] { 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127 };
#declare LR = 120093.99364185074;  // line rate, Hz
#declare TAU = 1.3860140286203796e-06;  // exposure, s
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
// film: 1040 x 4 samples spanning y/z in [-0.00705811776, 0.007490441463] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 0.9657589207, 4467.758373>
  right <0, 64.99944729, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 52272.867
  pigment { function { max(0.002, min(0.98, 0.290637 * (1 + 0.00413958 * ((y / 52272.867) - 0.0002161618512) / 0.007274279612 + 0.0145757 * sin(23.197896 * ((y / 52272.867) - 0.0002161618512) / 0.007274279612 + 3.53225)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 47.50301207, 12986.34447> + 389590 * <0.9393884776, 0.2423230836, 0.2425465136> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, 47.50301207, 12986.34447>;  // mm
#declare V_0 = <55162.95451, -6830.370512, -13884.9361>;  // mm/s
#declare TC_0 = 0.0010158709549108128;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.7877848137, 0.7877848137, 0.7706590569>] [0.44 rgb <0.7877848137, 0.7877848137, 0.7706590569>] [0.46 rgb <0.5994014887, 0.7278446648, 0.1284431761>] [1.00 rgb <0.5994014887, 0.7278446648, 0.1284431761>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.2382 diffuse 0.7618 } }
  no_shadow
  rotate <168.5162164, 253.4422618, 17.85446906>
  transform { Axis_Rotate_Trans(<-0.4038741611, -0.09000525135, -0.9103761403>, 0 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
