// validation scene pv0251 (seed 251)
#version 3.7;
#declare NS = 1;
#declare NLT = 53;
#declare LINES = array[53] { 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66 };
#declare LR = 4094.2468831871647;  // line rate, Hz
#declare TAU = 3.5941844203149464e-05;  // exposure, s
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
// film: 2512 x 4 samples spanning y/z in [-0.01717299303, 0.02242949657] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 10.41943405, 3964.397228>
  right <0, 157, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 17077.684
  pigment { function { max(0.002, min(0.98, 0.54223 * (1 + 0.043812 * ((y / 17077.684) - 0.002628251774) / 0.0198012448 + 0 * sin(3.2397752 * ((y / 17077.684) - 0.002628251774) / 0.0198012448 + 4.63409)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 17.73693975, 4733.563238> + 142007 * <-0.08954091544, 0.9218767048, -0.3769957102> color rgb FL }
light_source { <0, 17.73693975, 4733.563238> + 142007 * <0.3385895943, 0.8127743577, 0.4740832522> color rgb FL * 0.2148 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, 17.73693975, 4733.563238>;  // mm
#declare V_0 = <-5667.492453, 574.199599, -201.6140132>;  // mm/s
#declare TC_0 = 0.009769806545926223;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.07811299683, 0.07811299683, 0.0764148882>] [0.44 rgb <0.07811299683, 0.07811299683, 0.0764148882>] [0.46 rgb <0.05943380193, 0.07216961664, 0.0127358147>] [1.00 rgb <0.05943380193, 0.07216961664, 0.0127358147>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.5097 diffuse 0.4903 } }
  no_shadow
  rotate <138.4143134, 167.6340559, 209.9997063>
  transform { Axis_Rotate_Trans(<-0.6379654015, -0.539271002, -0.5497153199>, 604.06377 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
