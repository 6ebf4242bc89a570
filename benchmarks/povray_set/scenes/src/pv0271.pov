// validation scene pv0271 (seed 271)
#version 3.7;
#declare NS = 2;
#declare NLT = 51;
#declare LINES = array[51] { 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62 };
#declare LR = 77.60508913298652;  // line rate, Hz
#declare TAU = 0.003912605036044763;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.330954 * sin(628.3185307 * T + 0.010316));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 2752 x 4 samples spanning y/z in [-0.02613860046, 0.03153695544] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 8.048076731, 2981.677478>
  right <0, 171.9699061, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 22571.833
  pigment { function { max(0.002, min(0.98, 0.010227 * (1 + 0.300469 * ((y / 22571.833) - 0.00269917749) / 0.02883777795 + 0 * sin(7.7048685 * ((y / 22571.833) - 0.00269917749) / 0.02883777795 + 4.99167)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -13.28932114, 4453.188213> + 133596 * <0.1995881284, -0.1591483574, -0.9668693704> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, -13.28932114, 4453.188213>;  // mm
#declare V_0 = <126.4243719, 32.36856229, 0.8355385639>;  // mm/s
#declare TC_0 = 0.47677285617951726;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.6731244525, 0.6581661314, 0.6132911679>] [0.5 rgb <0.6731244525, 0.6581661314, 0.6132911679>] [0.5 rgb <0.5609370438, 0.05983328467, 0.0448749635>] [1.0 rgb <0.5609370438, 0.05983328467, 0.0448749635>] } }
  finish { ambient 0.5898 diffuse 0.4102 phong 0.1 phong_size 40 } }
  no_shadow
  rotate <112.3958387, 352.501086, 168.2567912>
  transform { Axis_Rotate_Trans(<0.8113225201, 0.1353748347, 0.5687085568>, 67.37242 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
