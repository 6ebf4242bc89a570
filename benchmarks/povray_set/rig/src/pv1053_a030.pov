// validation scene pv1053_a030 (seed 1053)
#version 3.7;
#declare NS = 2;
#declare NLT = 29;
#declare LINES = array[29] { 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34 };
#declare LR = 6155.070712928138;  // line rate, Hz
#declare TAU = 5.347464065845893e-05;  // exposure, s
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
// film: 2320 x 4 samples spanning y/z in [-0.0156639993, 0.01603013471] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 0.8375194299, 4574.916327>
  right <0, 144.9980111, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 34049.428
  pigment { function { max(0.002, min(0.98, 0.0370178 * (1 + 0.31243 * ((y / 34049.428) - 0.0001830677044) / 0.015847067 + 0 * sin(13.006009 * ((y / 34049.428) - 0.0001830677044) / 0.015847067 + 5.51649)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -133.5170354, 11796.59152> + 353898 * <-0.1587541903, 0.3569970528, -0.9205162744> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, -133.5170354, 11796.59152>;  // mm
#declare V_0 = <17388.51431, 3703.225302, -1373.550055>;  // mm/s
#declare TC_0 = 0.0032493534084006397;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.76854922, 0.76854922, 0.7518416283>] [0.44 rgb <0.76854922, 0.76854922, 0.7518416283>] [0.46 rgb <0.5847657109, 0.7100726489, 0.125306938>] [1.00 rgb <0.5847657109, 0.7100726489, 0.125306938>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.2103 diffuse 0.7897 phong 0.4951 phong_size 40 } }
  no_shadow
  rotate <300.1149365, 351.9605422, 96.74571401>
  transform { Axis_Rotate_Trans(<-0.1373939793, 0.287230304, 0.9479565638>, 8527.8231 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
