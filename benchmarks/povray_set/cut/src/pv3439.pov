// validation scene pv3439 (seed 3439)
#version 3.7;
#declare NS = 2;
#declare NLT = 87;
#declare LINES = array[87] { 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110 };
#declare LR = 501.2662744683805;  // line rate, Hz
#declare TAU = 0.0014765119745991254;  // exposure, s
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
// film: 1168 x 4 samples spanning y/z in [-0.02457249955, 0.02163953063] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -2.316569199, 1579.675243>
  right <0, 73, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 11787.992
  pigment { function { max(0.002, min(0.98, 0.812906 * (1 + -0.125017 * ((y / 11787.992) - -0.001466484462) / 0.02310601509 + 0.125455 * sin(16.968739 * ((y / 11787.992) - -0.001466484462) / 0.02310601509 + 1.42921)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 24.3685855, 2106.942142> + 63208.3 * <-0.02304684702, -0.7563282037, -0.6537862733> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, 24.3685855, 2106.942142>;  // mm
#declare V_0 = <-415.8340564, -69.66098768, -36.41386473>;  // mm/s
#declare TC_0 = 0.13366149572112557;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.07639920238, 0.07639920238, 0.07473835015>] [0.44 rgb <0.07639920238, 0.07639920238, 0.07473835015>] [0.46 rgb <0.05812982789, 0.07058621959, 0.01245639169>] [1.00 rgb <0.05812982789, 0.07058621959, 0.01245639169>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.2307 diffuse 0.7693 } }
  no_shadow
  rotate <277.8977033, 230.921148, 316.9760045>
  transform { Axis_Rotate_Trans(<-0.6231251514, -0.5032001613, -0.5987525727>, 0 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
