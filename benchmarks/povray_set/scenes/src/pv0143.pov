// validation scene pv0143 (seed 143)
#version 3.7;
#declare NS = 1;
#declare NLT = 87;
#declare LINES = array[87] { 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110 };
#declare LR = 217.88102821577831;  // line rate, Hz
#declare TAU = 0.0025843985698166057;  // exposure, s
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
// film: 2368 x 4 samples spanning y/z in [-0.02543584998, 0.03311486481] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 9.707398814, 2528.292763>
  right <0, 148.0333485, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 46267.791
  pigment { function { max(0.002, min(0.98, 0.530133 * (1 + 0.310389 * ((y / 46267.791) - 0.003839507417) / 0.0292753574 + 0 * sin(10.200006 * ((y / 46267.791) - 0.003839507417) / 0.0292753574 + 2.6448)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -33.00987292, 13456.94437> + 403708 * <-0.7838126612, 0.2712452333, -0.5586266513> color rgb FL }
light_source { <0, -33.00987292, 13456.94437> + 403708 * <-0.2746215375, 0.44027033, 0.8548362695> color rgb FL * 0.653 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, -33.00987292, 13456.94437>;  // mm
#declare V_0 = <-190.3829152, 21.18375186, 65.05054619>;  // mm/s
#declare TC_0 = 0.3075072692132084;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.1413720115, 0.1413720115, 0.1382987069>] [0.44 rgb <0.1413720115, 0.1413720115, 0.1382987069>] [0.46 rgb <0.1075656609, 0.1306154454, 0.02304978448>] [1.00 rgb <0.1075656609, 0.1306154454, 0.02304978448>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.1089 diffuse 0.8911 } }
  no_shadow
  rotate <336.1431796, 151.9258361, 201.7354225>
  transform { Axis_Rotate_Trans(<0.328788771, -0.8077522828, -0.4893201342>, 98.746556 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
