// validation scene pv0181 (seed 181)
#version 3.7;
#declare NS = 1;
#declare NLT = 41;
#declare LINES = array[41] { 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51 };
#declare LR = 12743.389662813908;  // line rate, Hz
#declare TAU = 4.495952815345694e-06;  // exposure, s
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
// film: 668 x 4 samples spanning y/z in [-0.08257494041, 0.06227358713] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -11.71861213, 1154.466106>
  right <0, 167.2227155, 0>
  up <1, 0, 0>
  aperture 121.00008 blur_samples 19 focal_point <0, -98.45439704, 9699.294> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 14785.971
  pigment { function { max(0.002, min(0.98, 0.468665 * (1 + -0.111216 * ((y / 14785.971) - -0.01015067664) / 0.07242426377 + 0.108285 * sin(19.520431 * ((y / 14785.971) - -0.01015067664) / 0.07242426377 + 3.13829)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -443.5502464, 7038.749073> + 211162 * <0.3032778675, 0.6485195667, -0.698172548> color rgb FL }
light_source { <0, -443.5502464, 7038.749073> + 211162 * <-0.8912214167, 0.2371320955, 0.3866429304> color rgb FL * 0.3482 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, -443.5502464, 7038.749073>;  // mm
#declare V_0 = <-24650.35986, 17803.69221, 6612.985513>;  // mm/s
#declare TC_0 = 0.0024326337670157057;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.2198664866, 0.2198664866, 0.2150867804>] [0.44 rgb <0.2198664866, 0.2198664866, 0.2150867804>] [0.46 rgb <0.1672897181, 0.2031375148, 0.03584779673>] [1.00 rgb <0.1672897181, 0.2031375148, 0.03584779673>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.5384 diffuse 0.4616 phong 0.678 phong_size 40 } }
  no_shadow
  rotate <154.8153629, 60.63614967, 190.634813>
  transform { Axis_Rotate_Trans(<-0.2887686391, 0.8872094602, -0.3598222433>, 11784.792 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
