// validation scene pv0174 (seed 174)
#version 3.7;
#declare NS = 4;
#declare NLT = 37;
#declare LINES = array[37] { 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45 };
#declare LR = 646.844116365346;  // line rate, Hz
#declare TAU = 0.0009227189366228796;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.238317 * sin(628.3185307 * T + 5.81569));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 1392 x 4 samples spanning y/z in [0.1285988953, 0.1599394063] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 400.4853687, 2775.95984>
  right <0, 87, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 28118.898
  pigment { function { max(0.002, min(0.98, 0.0381096 * (1 + 0.307021 * ((y / 28118.898) - 0.1442691508) / 0.01567025552 + 0 * sin(4.9536639 * ((y / 28118.898) - 0.1442691508) / 0.01567025552 + 1.46298)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 924.2454056, 6895.307398> + 206859 * <0.5189616987, -0.6832882524, -0.5136106692> color rgb FL }
light_source { <0, 924.2454056, 6895.307398> + 206859 * <-0.5713283155, -0.1627548278, -0.8044220422> color rgb FL * 0.6091 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, 924.2454056, 6895.307398>;  // mm
#declare V_0 = <-1356.39203, 1983.230467, 404.6262378>;  // mm/s
#declare TC_0 = 0.041741123273586436;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.8954794393, 0.8954794393, 0.876012495>] [0.44 rgb <0.8954794393, 0.8954794393, 0.876012495>] [0.46 rgb <0.6813430517, 0.8273451342, 0.1460020825>] [1.00 rgb <0.6813430517, 0.8273451342, 0.1460020825>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.4444 diffuse 0.5556 } }
  no_shadow
  rotate <338.2275958, 203.2991136, 222.3040682>
  transform { Axis_Rotate_Trans(<-0.8544472236, 0.499767801, 0.1419580473>, 1383.8231 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
