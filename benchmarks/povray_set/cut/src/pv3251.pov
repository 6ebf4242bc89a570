// validation scene pv3251 (seed 3251)
#version 3.7;
#declare NS = 1;
#declare NLT = 129;
#declare LINES = array[129] { 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165 };
#declare LR = 18354.300996663347;  // line rate, Hz
#declare TAU = 3.887529879884959e-06;  // exposure, s
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
// film: 452 x 4 samples spanning y/z in [-0.02672935433, 0.03241593179] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 5.43224402, 1910.549554>
  right <0, 113, 0>
  up <1, 0, 0>
  aperture 98.438981 blur_samples 19 focal_point <0, 26.19748137, 9213.7957> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 42222.814
  pigment { function { max(0.002, min(0.98, 0.0118895 * (1 + -0.186109 * ((y / 42222.814) - 0.002843288733) / 0.02957264306 + 0.0952818 * sin(20.407992 * ((y / 42222.814) - 0.002843288733) / 0.02957264306 + 5.14581)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 324.8133654, 11609.99531> + 348300 * <-0.5185477259, -0.164211692, -0.8391321565> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, 324.8133654, 11609.99531>;  // mm
#declare V_0 = <33076.95658, 16257.87573, -3260.443543>;  // mm/s
#declare TC_0 = 0.005502797410719205;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.7297085601, 0.7297085601, 0.7297085601>] [0.925 rgb <0.7297085601, 0.7297085601, 0.7297085601>] [0.935 rgb <0.03965807392, 0.03965807392, 0.03965807392>] [1.0 rgb <0.03965807392, 0.03965807392, 0.03965807392>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.4362 diffuse 0.5638 } }
  no_shadow
  rotate <181.5509175, 65.41874658, 110.1039257>
  transform { Axis_Rotate_Trans(<-0.1315678545, 0.9912133136, -0.01364062048>, 14777.235 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
