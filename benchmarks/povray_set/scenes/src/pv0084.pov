// validation scene pv0084 (seed 84)
#version 3.7;
#declare NS = 1;
#declare NLT = 155;
#declare LINES = array[155] { 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198 };
#declare LR = 4226.859582028231;  // line rate, Hz
#declare TAU = 1.801958598772114e-05;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.27797 * sin(753.9822369 * T + 0.659666));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 508 x 4 samples spanning y/z in [-0.01038552027, 0.01214821755] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 4.967275198, 5635.993505>
  right <0, 127, 0>
  up <1, 0, 0>
  aperture 13.010425 blur_samples 19 focal_point <0, 7.041108189, 7989.0158> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 11526.485
  pigment { function { max(0.002, min(0.98, 0.0381356 * (1 + -0.0468457 * ((y / 11526.485) - 0.0008813486378) / 0.01126686891 + 0 * sin(15.838801 * ((y / 11526.485) - 0.0008813486378) / 0.01126686891 + 3.17253)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -22.96784171, 5753.800325> + 172614 * <0.1755184783, 0.3494477217, -0.9203692485> color rgb FL }
light_source { <0, -22.96784171, 5753.800325> + 172614 * <-0.7081798929, -0.6466678807, 0.2833758836> color rgb FL * 0.6949 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, -22.96784171, 5753.800325>;  // mm
#declare V_0 = <-1907.377092, 304.0523587, 159.1023986>;  // mm/s
#declare TC_0 = 0.028626453671294884;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.88333053, 0.88333053, 0.8641276924>] [0.44 rgb <0.88333053, 0.88333053, 0.8641276924>] [0.46 rgb <0.6720993163, 0.8161205984, 0.1440212821>] [1.00 rgb <0.6720993163, 0.8161205984, 0.1440212821>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.121 diffuse 0.879 } }
  no_shadow
  rotate <83.74719452, 22.47275988, 131.8042606>
  transform { Axis_Rotate_Trans(<0.8334620051, 0.1696020963, -0.5259051388>, 0 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
