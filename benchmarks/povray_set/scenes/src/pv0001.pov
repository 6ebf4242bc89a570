// validation scene pv0001 (seed 1)
#version 3.7;
#declare NS = 1;
#declare NLT = 46;
#declare LINES = array[46] { 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70 };
#declare LR = 237.6312480389279;  // line rate, Hz
#declare TAU = 0.00047281040017430975;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.233627 * sin(628.3185307 * T + 0.138269));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 492 x 4 samples spanning y/z in [-0.01228227672, 0.009568588971] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -7.637765881, 5629.067597>
  right <0, 123, 0>
  up <1, 0, 0>
  aperture 16.862923 blur_samples 19 focal_point <0, -12.94627183, 9541.4602> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 31540.759
  pigment { function { max(0.002, min(0.98, 0.719241 * (1 + 0.256655 * ((y / 31540.759) - -0.001356843873) / 0.01092543284 + 0 * sin(11.956084 * ((y / 31540.759) - -0.001356843873) / 0.01092543284 + 1.80898)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 13.51318993, 6243.519486> + 187306 * <-0.3706191825, -0.3622898195, -0.8552119668> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, 13.51318993, 6243.519486>;  // mm
#declare V_0 = <190.255122, 14.40563155, 1.081896434>;  // mm/s
#declare TC_0 = 0.2903658528473354;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.1465724199, 0.1465724199, 0.1433860629>] [0.44 rgb <0.1465724199, 0.1465724199, 0.1433860629>] [0.46 rgb <0.1115224934, 0.1354201705, 0.02389767715>] [1.00 rgb <0.1115224934, 0.1354201705, 0.02389767715>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.2652 diffuse 0.7348 phong 0.3573 phong_size 40 } }
  no_shadow
  rotate <243.8467864, 281.363716, 35.91917074>
  transform { Axis_Rotate_Trans(<0.3200140236, -0.02443833294, -0.9470975623>, 0 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
