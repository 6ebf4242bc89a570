// validation scene pv0264 (seed 264)
#version 3.7;
#declare NS = 1;
#declare NLT = 71;
#declare LINES = array[71] { 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88 };
#declare LR = 7118.789336327983;  // line rate, Hz
#declare TAU = 1.3915753846494857e-05;  // exposure, s
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
// film: 2736 x 4 samples spanning y/z in [-0.07087571429, 0.05285736462] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -12.45829294, 1382.845063>
  right <0, 171.1036772, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 12091.701
  pigment { function { max(0.002, min(0.98, 0.482347 * (1 + 0.114174 * ((y / 12091.701) - -0.009009174838) / 0.06186653945 + 0.0357962 * sin(4.0736275 * ((y / 12091.701) - -0.009009174838) / 0.06186653945 + 2.72765)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 118.9398677, 4628.938894> + 138868 * <0.4403628772, 0.1052749879, -0.8916264427> color rgb FL }
light_source { <0, 118.9398677, 4628.938894> + 138868 * <0.06090021392, 0.611932916, -0.7885615197> color rgb FL * 0.6947 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, 118.9398677, 4628.938894>;  // mm
#declare V_0 = <-8259.766135, -1038.655972, 351.4359397>;  // mm/s
#declare TC_0 = 0.0074450861650779635;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.2151816283, 0.2103998144, 0.1960543725>] [0.5 rgb <0.2151816283, 0.2103998144, 0.1960543725>] [0.5 rgb <0.1793180236, 0.01912725585, 0.01434544189>] [1.0 rgb <0.1793180236, 0.01912725585, 0.01434544189>] } }
  finish { ambient 0.5003 diffuse 0.4997 phong 0.1 phong_size 40 } }
  no_shadow
  rotate <26.67778636, 262.4880917, 78.17310239>
  transform { Axis_Rotate_Trans(<-0.8950087373, 0.4330268063, 0.1069913322>, 5697.7421 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
