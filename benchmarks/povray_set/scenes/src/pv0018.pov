// validation scene pv0018 (seed 18)
#version 3.7;
#declare NS = 1;
#declare NLT = 31;
#declare LINES = array[31] { 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37 };
#declare LR = 431.5615663351672;  // line rate, Hz
#declare TAU = 9.08972945490434e-05;  // exposure, s
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
// film: 1680 x 4 samples spanning y/z in [-0.05956476107, 0.06636900903] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 2.836594326, 833.7715921>
  right <0, 105, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 17167.68
  pigment { function { max(0.002, min(0.98, 0.115645 * (1 + -0.102849 * ((y / 17167.68) - 0.003402123979) / 0.06296688505 + 0.146473 * sin(6.7124148 * ((y / 17167.68) - 0.003402123979) / 0.06296688505 + 0.531677)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 143.1501316, 4297.920675> + 128938 * <-0.3722839741, 0.6374755721, -0.6745587725> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, 143.1501316, 4297.920675>;  // mm
#declare V_0 = <-1282.812907, 917.1620233, -156.0670045>;  // mm/s
#declare TC_0 = 0.05097766278592557;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.7881422848, 0.7706280118, 0.7180851928>] [0.5 rgb <0.7881422848, 0.7706280118, 0.7180851928>] [0.5 rgb <0.6567852373, 0.07005709198, 0.05254281899>] [1.0 rgb <0.6567852373, 0.07005709198, 0.05254281899>] } }
  finish { ambient 0.5455 diffuse 0.4545 phong 0.1 phong_size 40 } }
  no_shadow
  rotate <127.751964, 286.7737284, 143.3725134>
  transform { Axis_Rotate_Trans(<0.1031736134, 0.5876101374, 0.8025394271>, 1362.7455 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
