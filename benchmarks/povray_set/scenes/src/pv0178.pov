// validation scene pv0178 (seed 178)
#version 3.7;
#declare NS = 1;
#declare NLT = 35;
#declare LINES = array[35] { 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43 };
#declare LR = 110.49921552519123;  // line rate, Hz
#declare TAU = 0.001117365719358294;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.326635 * sin(628.3185307 * T + 4.60976));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 1200 x 4 samples spanning y/z in [-0.1128408723, -0.06190151198] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -128.6400019, 1472.338864>
  right <0, 75, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 26890.758
  pigment { function { max(0.002, min(0.98, 0.0204383 * (1 + 0.0259305 * ((y / 26890.758) - -0.08737119216) / 0.02546968018 + 0.203244 * sin(7.9439159 * ((y / 26890.758) - -0.08737119216) / 0.02546968018 + 3.73842)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -546.7734892, 4894.612327> + 146838 * <-0.02879335085, 0.9135987347, -0.4055962215> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, -546.7734892, 4894.612327>;  // mm
#declare V_0 = <249.3754531, -117.6365882, -116.5480104>;  // mm/s
#declare TC_0 = 0.23529578808704402;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.7924861072, 0.7924861072, 0.7752581484>] [0.44 rgb <0.7924861072, 0.7924861072, 0.7752581484>] [0.46 rgb <0.6029785598, 0.7321882512, 0.1292096914>] [1.00 rgb <0.6029785598, 0.7321882512, 0.1292096914>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.2621 diffuse 0.7379 } }
  no_shadow
  rotate <319.2791507, 128.5979865, 11.39626532>
  transform { Axis_Rotate_Trans(<-0.5833142654, -0.4127720317, 0.6995453649>, 0 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
