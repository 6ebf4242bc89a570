// validation scene pv0246 (seed 246)
#version 3.7;
#declare NS = 1;
#declare NLT = 37;
#declare LINES = array[37] { 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46 };
#declare LR = 101.2784863016118;  // line rate, Hz
#declare TAU = 0.0010137578180010316;  // exposure, s
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
// film: 1936 x 4 samples spanning y/z in [-0.01790606615, 0.01456378461] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -6.227562751, 3726.533912>
  right <0, 121, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 47136.976
  pigment { function { max(0.002, min(0.98, 0.24921 * (1 + 0.388927 * ((y / 47136.976) - -0.00167114077) / 0.01623492538 + 0.181403 * sin(10.630971 * ((y / 47136.976) - -0.00167114077) / 0.01623492538 + 0.0465556)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -61.48865065, 7994.887398> + 239847 * <0.2505776698, 0.2256463076, -0.9414321937> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, -61.48865065, 7994.887398>;  // mm
#declare V_0 = <-225.3344209, -22.13260465, -85.89718285>;  // mm/s
#declare TC_0 = 0.2764654273822257;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.8124930222, 0.7944376217, 0.7402714202>] [0.5 rgb <0.8124930222, 0.7944376217, 0.7402714202>] [0.5 rgb <0.6770775185, 0.07222160197, 0.05416620148>] [1.0 rgb <0.6770775185, 0.07222160197, 0.05416620148>] } }
  finish { ambient 0.4817 diffuse 0.5183 phong 0.4453 phong_size 40 } }
  no_shadow
  rotate <326.3959389, 216.2928163, 156.1897324>
  transform { Axis_Rotate_Trans(<0.1323153017, -0.7798058651, 0.6118786429>, 168.59048 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
