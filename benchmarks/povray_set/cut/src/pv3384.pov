// validation scene pv3384 (seed 3384)
#version 3.7;
#declare NS = 1;
#declare NLT = 152;
#declare LINES = array[152] { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151 };
#declare LR = 365.9517388140408;  // line rate, Hz
#declare TAU = 0.0013855092436937803;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.290347 * sin(628.3185307 * T + 5.16706));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 2640 x 4 samples spanning y/z in [-0.03207815586, 0.04459688674] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 13.46977142, 2151.938811>
  right <0, 165, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 27273.795
  pigment { function { max(0.002, min(0.98, 0.0894531 * (1 + -0.0372168 * ((y / 27273.795) - 0.006259365439) / 0.0383375213 + 0.128261 * sin(8.6631552 * ((y / 27273.795) - 0.006259365439) / 0.0383375213 + 3.77973)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -26.74680231, 8673.492825> + 260205 * <-0.3955165293, 0.3571123303, -0.846189966> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, -26.74680231, 8673.492825>;  // mm
#declare V_0 = <467.0512764, 219.1575866, -98.98386269>;  // mm/s
#declare TC_0 = 0.1666886464255804;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.7261015132, 0.7261015132, 0.7261015132>] [0.925 rgb <0.7261015132, 0.7261015132, 0.7261015132>] [0.935 rgb <0.03946203876, 0.03946203876, 0.03946203876>] [1.0 rgb <0.03946203876, 0.03946203876, 0.03946203876>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.5097 diffuse 0.4903 } }
  no_shadow
  rotate <235.1499033, 337.0198962, 248.9029904>
  transform { Axis_Rotate_Trans(<0.841365696, 0.5100073126, -0.1788751148>, 431.99107 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
