// validation scene pv0154 (seed 154)
#version 3.7;
#declare NS = 1;
#declare NLT = 157;
#declare LINES = array[157] { 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200 };
#declare LR = 24046.215205745513;  // line rate, Hz
#declare TAU = 2.76282394971618e-06;  // exposure, s
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
// film: 456 x 4 samples spanning y/z in [-0.01358817833, 0.01509286231] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 2.990372204, 3974.751176>
  right <0, 114, 0>
  up <1, 0, 0>
  aperture 21.439186 blur_samples 19 focal_point <0, 6.830344317, 9078.7759> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 71486.503
  pigment { function { max(0.002, min(0.98, 0.0281812 * (1 + 0.123715 * ((y / 71486.503) - 0.0007523419886) / 0.01434052032 + 0 * sin(20.254929 * ((y / 71486.503) - 0.0007523419886) / 0.01434052032 + 3.46422)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -104.9923203, 14237.4076> + 427122 * <-0.1217944948, -0.6397275497, -0.7588904817> color rgb FL }
light_source { <0, -104.9923203, 14237.4076> + 427122 * <0.4142412824, -0.7635647451, -0.4953514308> color rgb FL * 0.3139 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, -104.9923203, 14237.4076>;  // mm
#declare V_0 = <-12136.71949, -19489.39853, 496.6699447>;  // mm/s
#declare TC_0 = 0.005073563509106821;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.638310348, 0.6241256736, 0.5815716504>] [0.5 rgb <0.638310348, 0.6241256736, 0.5815716504>] [0.5 rgb <0.53192529, 0.0567386976, 0.0425540232>] [1.0 rgb <0.53192529, 0.0567386976, 0.0425540232>] } }
  finish { ambient 0.2582 diffuse 0.7418 phong 0.1 phong_size 40 } }
  no_shadow
  rotate <166.7858533, 81.70622996, 3.398390806>
  transform { Axis_Rotate_Trans(<0.7590519715, -0.2065243152, -0.6174040911>, 0 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
