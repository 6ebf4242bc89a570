// validation scene pv0127 (seed 127)
#version 3.7;
#declare NS = 1;
#declare NLT = 43;
#declare LINES = array[43] { 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53 };
#declare LR = 141.60830185986433;  // line rate, Hz
#declare TAU = 0.0006346070367123671;  // exposure, s
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
// film: 688 x 4 samples spanning y/z in [-0.3032638185, -0.2435249554] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -787.1565023, 2879.197745>
  right <0, 172, 0>
  up <1, 0, 0>
  aperture 36.47973 blur_samples 19 focal_point <0, -3434.638668, 12562.945> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 27768.176
  pigment { function { max(0.002, min(0.98, 0.223361 * (1 + -0.375042 * ((y / 27768.176) - -0.2733943869) / 0.02986943156 + 0.240972 * sin(23.050534 * ((y / 27768.176) - -0.2733943869) / 0.02986943156 + 6.23307)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -2301.819281, 8435.871692> + 253076 * <-0.6196510892, -0.7365025076, -0.2712869035> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, -2301.819281, 8435.871692>;  // mm
#declare V_0 = <-252.9632339, 204.909312, 28.48136626>;  // mm/s
#declare TC_0 = 0.22597545186063472;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.675803006, 0.675803006, 0.6611116363>] [0.44 rgb <0.675803006, 0.675803006, 0.6611116363>] [0.46 rgb <0.5141979394, 0.6243832121, 0.1101852727>] [1.00 rgb <0.5141979394, 0.6243832121, 0.1101852727>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.3395 diffuse 0.6605 } }
  no_shadow
  rotate <194.9815751, 244.6604232, 301.5027958>
  transform { Axis_Rotate_Trans(<0.3807981963, 0.1767169469, 0.9076143754>, 96.406045 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
