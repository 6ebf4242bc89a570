// validation scene pv3987 (seed 3987)
#version 3.7;
#declare NS = 1;
#declare NLT = 121;
#declare LINES = array[121] { 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154 };
#declare LR = 12995.363585029196;  // line rate, Hz
#declare TAU = 6.0388016004615925e-05;  // exposure, s
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
// film: 668 x 4 samples spanning y/z in [-0.04279676418, 0.05660177492] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 11.596935, 1680.105176>
  right <0, 167, 0>
  up <1, 0, 0>
  aperture 26.313931 blur_samples 19 focal_point <0, 25.46767266, 3689.6274> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 28223.173
  pigment { function { max(0.002, min(0.98, 0.559888 * (1 + 0.0896647 * ((y / 28223.173) - 0.006902505369) / 0.04969926955 + 0 * sin(13.2632 * ((y / 28223.173) - 0.006902505369) / 0.04969926955 + 4.1743)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -239.9639079, 5670.328951> + 170110 * <-0.3170322125, -0.3007903594, -0.8994530204> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, -239.9639079, 5670.328951>;  // mm
#declare V_0 = <7875.816595, 8.709944044, -161.9030541>;  // mm/s
#declare TC_0 = 0.007233348985194154;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.1425292458, 0.1425292458, 0.1394307839>] [0.44 rgb <0.1425292458, 0.1425292458, 0.1394307839>] [0.46 rgb <0.1084461653, 0.1316846293, 0.02323846399>] [1.00 rgb <0.1084461653, 0.1316846293, 0.02323846399>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.2601 diffuse 0.7399 } }
  no_shadow
  rotate <115.9071953, 314.834443, 44.39315971>
  transform { Axis_Rotate_Trans(<0.2131679666, 0.6236817461, 0.752050861>, 1691.7594 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
