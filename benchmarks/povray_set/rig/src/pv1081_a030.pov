// validation scene pv1081_a030 (seed 1081)
#version 3.7;
#declare NS = 1;
#declare NLT = 59;
#declare LINES = array[59] { 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73 };
#declare LR = 14981.453247276284;  // line rate, Hz
#declare TAU = 5.989044119762316e-06;  // exposure, s
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
// film: 2192 x 4 samples spanning y/z in [0.3035745851, 0.4475145967] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 357.4378548, 951.7853898>
  right <0, 137, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 3207.7193
  pigment { function { max(0.002, min(0.98, 0.467995 * (1 + 0.109535 * ((y / 3207.7193) - 0.3755445909) / 0.07197000578 + 0 * sin(20.917062 * ((y / 3207.7193) - 0.3755445909) / 0.07197000578 + 1.36401)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 569.7613565, 1478.611139> + 44358.3 * <0.7478552915, 0.5603135745, -0.3560353371> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, 569.7613565, 1478.611139>;  // mm
#declare V_0 = <18795.00177, 2068.682113, 18.77018083>;  // mm/s
#declare TC_0 = 0.0029369647439242558;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.2686346467, 0.2686346467, 0.262794763>] [0.44 rgb <0.2686346467, 0.2686346467, 0.262794763>] [0.46 rgb <0.2043959268, 0.248195054, 0.04379912717>] [1.00 rgb <0.2043959268, 0.248195054, 0.04379912717>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.3939 diffuse 0.6061 phong 0.506 phong_size 40 } }
  no_shadow
  rotate <245.8947009, 341.1525745, 25.13439322>
  transform { Axis_Rotate_Trans(<0.320548209, 0.4457165741, -0.8358143222>, 0 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
