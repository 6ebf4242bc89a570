// validation scene pv0273 (seed 273)
#version 3.7;
#declare NS = 1;
#declare NLT = 143;
#declare LINES = array[143] { 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182 };
#declare LR = 26443.566444647215;  // line rate, Hz
#declare TAU = 1.2511664347821167e-05;  // exposure, s
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
// film: 800 x 4 samples spanning y/z in [-0.09787472804, -0.009934150571] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -122.5928709, 2274.262983>
  right <0, 200, 0>
  up <1, 0, 0>
  aperture 27.456974 blur_samples 19 focal_point <0, -246.2660398, 4568.5669> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 29291.359
  pigment { function { max(0.002, min(0.98, 0.0474835 * (1 + 0.279916 * ((y / 29291.359) - -0.0539044393) / 0.04397028873 + 0.123984 * sin(22.26681 * ((y / 29291.359) - -0.0539044393) / 0.04397028873 + 4.03689)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -455.9173673, 5483.441961> + 164503 * <-0.02432591702, -0.2572572607, -0.9660367237> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, -455.9173673, 5483.441961>;  // mm
#declare V_0 = <-24152.83487, 29735.84784, 2460.764071>;  // mm/s
#declare TC_0 = 0.0030253105294045478;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.6829699331, 0.6829699331, 0.6681227607>] [0.44 rgb <0.6829699331, 0.6829699331, 0.6681227607>] [0.46 rgb <0.5196510361, 0.6310048295, 0.1113537934>] [1.00 rgb <0.5196510361, 0.6310048295, 0.1113537934>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.5806 diffuse 0.4194 } }
  no_shadow
  rotate <179.5128101, 323.0648744, 75.35108514>
  transform { Axis_Rotate_Trans(<-0.9559230032, -0.1437098715, -0.2560443024>, 0 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
// ball 1: tennis
#declare C0_1 = <0, -200.1147348, 6092.787149>;  // mm
#declare V_1 = <-29838.87294, 3364.080269, 498.0208579>;  // mm/s
#declare TC_1 = 0.005650974068652358;  // s
#declare P_1 = C0_1 + V_1 * (T - TC_1);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.6829699331, 0.6829699331, 0.6681227607>] [0.44 rgb <0.6829699331, 0.6829699331, 0.6681227607>] [0.46 rgb <0.5196510361, 0.6310048295, 0.1113537934>] [1.00 rgb <0.5196510361, 0.6310048295, 0.1113537934>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.5806 diffuse 0.4194 } }
  no_shadow
  rotate <293.4673207, 64.72587085, 194.1355008>
  transform { Axis_Rotate_Trans(<-0.9559230032, -0.1437098715, -0.2560443024>, 0 * (T - TC_1)) }
  scale 33.5
  translate P_1 }
#end
