// validation scene pv0295 (seed 295)
#version 3.7;
#declare NS = 1;
#declare NLT = 79;
#declare LINES = array[79] { 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100 };
#declare LR = 38740.13282716156;  // line rate, Hz
#declare TAU = 1.1209817806086685e-06;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.124176 * sin(753.9822369 * T + 5.11613));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 1600 x 4 samples spanning y/z in [-0.3950099679, -0.2998103699] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -364.928189, 1050.424604>
  right <0, 100, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 38926.245
  pigment { function { max(0.002, min(0.98, 0.294886 * (1 + -0.335955 * ((y / 38926.245) - -0.3474101689) / 0.04759979901 + 0.13738 * sin(24.573395 * ((y / 38926.245) - -0.3474101689) / 0.04759979901 + 0.374989)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -2723.463197, 9024.310031> + 270729 * <0.4984747192, -0.2248424496, -0.8372388113> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, -2723.463197, 9024.310031>;  // mm
#declare V_0 = <38695.39452, -2910.188647, -3476.790943>;  // mm/s
#declare TC_0 = 0.0015745944979628868;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.7108052987, 0.7108052987, 0.6953530096>] [0.44 rgb <0.7108052987, 0.7108052987, 0.6953530096>] [0.46 rgb <0.5408301186, 0.6567222868, 0.1158921683>] [1.00 rgb <0.5408301186, 0.6567222868, 0.1158921683>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.4193 diffuse 0.5807 phong 0.3294 phong_size 40 } }
  no_shadow
  rotate <281.5049422, 241.5923791, 310.2493492>
  transform { Axis_Rotate_Trans(<-0.2177903051, 0.9753319301, -0.03598623583>, 15924.55 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
