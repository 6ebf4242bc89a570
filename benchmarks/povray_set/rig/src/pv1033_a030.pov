// validation scene pv1033_a030 (seed 1033)
#version 3.7;
#declare NS = 1;
#declare NLT = 43;
#declare LINES = array[43] { 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53 };
#declare LR = 797.9504415365361;  // line rate, Hz
#declare TAU = 0.0005770956140045835;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.342213 * sin(753.9822369 * T + 1.11984));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 2896 x 4 samples spanning y/z in [-0.0869708189, 0.09009375975] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 1.596175523, 1022.22591>
  right <0, 181, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 28161.221
  pigment { function { max(0.002, min(0.98, 0.0203226 * (1 + 0.260157 * ((y / 28161.221) - 0.001561470422) / 0.08853228933 + 0 * sin(4.454718 * ((y / 28161.221) - 0.001561470422) / 0.08853228933 + 1.1042)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -242.6017941, 8800.65656> + 264020 * <-0.1588423445, 0.1108423948, -0.9810622167> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, -242.6017941, 8800.65656>;  // mm
#declare V_0 = <1683.415586, -2631.167896, -1199.600415>;  // mm/s
#declare TC_0 = 0.04010274114064113;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.6667150736, 0.6518991831, 0.6074515115>] [0.5 rgb <0.6667150736, 0.6518991831, 0.6074515115>] [0.5 rgb <0.5555958947, 0.0592635621, 0.04444767158>] [1.0 rgb <0.5555958947, 0.0592635621, 0.04444767158>] } }
  finish { ambient 0.539 diffuse 0.461 phong 0.5236 phong_size 40 } }
  no_shadow
  rotate <2.451944628, 18.36803214, 339.9117245>
  transform { Axis_Rotate_Trans(<-0.1007271779, 0.7676420421, -0.6329136836>, 2503.8723 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
