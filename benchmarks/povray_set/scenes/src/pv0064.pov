// validation scene pv0064 (seed 64)
#version 3.7;
#declare NS = 1;
#declare NLT = 153;
#declare LINES = array[153] { 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196 };
#declare LR = 3737.056187159026;  // line rate, Hz
#declare TAU = 0.00010171294752099858;  // exposure, s
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
// film: 3104 x 4 samples spanning y/z in [-0.1987705073, -0.05741892499] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -173.5056913, 1354.510916>
  right <0, 191.4622613, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 15385.802
  pigment { function { max(0.002, min(0.98, 0.552299 * (1 + 0.217435 * ((y / 15385.802) - -0.1280947162) / 0.07067579117 + 0 * sin(24.947356 * ((y / 15385.802) - -0.1280947162) / 0.07067579117 + 2.4543)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -240.2784811, 3750.1083> + 112503 * <-0.7540747433, 0.5741538382, -0.3189336162> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, -240.2784811, 3750.1083>;  // mm
#declare V_0 = <1911.578436, -2661.325095, 750.9065848>;  // mm/s
#declare TC_0 = 0.032110836441885574;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.2552129714, 0.2495415721, 0.232527374>] [0.5 rgb <0.2552129714, 0.2495415721, 0.232527374>] [0.5 rgb <0.2126774762, 0.02268559746, 0.0170141981>] [1.0 rgb <0.2126774762, 0.02268559746, 0.0170141981>] } }
  finish { ambient 0.2975 diffuse 0.7025 phong 0.7226 phong_size 40 } }
  no_shadow
  rotate <58.21762461, 357.4742699, 220.263762>
  transform { Axis_Rotate_Trans(<0.4352640784, 0.1649456203, -0.8850639098>, 2616.5823 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
