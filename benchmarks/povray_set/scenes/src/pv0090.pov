// validation scene pv0090 (seed 90)
#version 3.7;
#declare NS = 2;
#declare NLT = 59;
#declare LINES = array[59] { 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73 };
#declare LR = 9201.277449440859;  // line rate, Hz
#declare TAU = 5.537437422836274e-05;  // exposure, s
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
// film: 3104 x 4 samples spanning y/z in [-0.02665109078, 0.02931438222] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 4.616047288, 3466.42295>
  right <0, 194, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 28032.936
  pigment { function { max(0.002, min(0.98, 0.0972842 * (1 + 0.11909 * ((y / 28032.936) - 0.001331645721) / 0.0279827365 + 0.217819 * sin(20.768998 * ((y / 28032.936) - 0.001331645721) / 0.0279827365 + 6.00643)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 11.22790078, 5353.567282> + 160607 * <-0.4225633418, -0.1174879402, -0.8986861555> color rgb FL }
light_source { <0, 11.22790078, 5353.567282> + 160607 * <-0.6930933888, -0.6513144152, 0.3088868513> color rgb FL * 0.362 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, 11.22790078, 5353.567282>;  // mm
#declare V_0 = <11618.18224, 1425.474642, -3316.239718>;  // mm/s
#declare TC_0 = 0.004781944707326892;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.7332784657, 0.7332784657, 0.7173376295>] [0.44 rgb <0.7332784657, 0.7332784657, 0.7173376295>] [0.46 rgb <0.5579292674, 0.677485539, 0.1195562716>] [1.00 rgb <0.5579292674, 0.677485539, 0.1195562716>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.4304 diffuse 0.5696 } }
  no_shadow
  rotate <171.410572, 167.9123669, 31.28778423>
  transform { Axis_Rotate_Trans(<0.2077219634, -0.9636635751, 0.1679407633>, 8491.8899 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
