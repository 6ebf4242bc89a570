// validation scene pv0222 (seed 222)
#version 3.7;
#declare NS = 2;
#declare NLT = 16;
#declare LINES = array[16] { 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23 };
#declare LR = 3394.2935327436185;  // line rate, Hz
#declare TAU = 6.47664709614691e-05;  // exposure, s
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
// film: 2336 x 4 samples spanning y/z in [-0.01450624134, 0.01776738936] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 7.376418455, 4523.817024>
  right <0, 146, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 52769.896
  pigment { function { max(0.002, min(0.98, 0.690106 * (1 + -0.135712 * ((y / 52769.896) - 0.001630574008) / 0.01613681535 + 0.227658 * sin(5.978745 * ((y / 52769.896) - 0.001630574008) / 0.01613681535 + 2.81399)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -67.58502451, 9724.729778> + 291742 * <-0.083038837, -0.08834246757, -0.992622869> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, -67.58502451, 9724.729778>;  // mm
#declare V_0 = <-8477.671119, 97.46636686, 794.3396271>;  // mm/s
#declare TC_0 = 0.006776078667954514;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.1129557999, 0.1129557999, 0.110500239>] [0.44 rgb <0.1129557999, 0.1129557999, 0.110500239>] [0.46 rgb <0.08594463035, 0.1043613369, 0.0184167065>] [1.00 rgb <0.08594463035, 0.1043613369, 0.0184167065>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.4662 diffuse 0.5338 phong 0.575 phong_size 40 } }
  no_shadow
  rotate <198.7381657, 88.99862021, 290.3810397>
  transform { Axis_Rotate_Trans(<-0.218309889, 0.7449300502, -0.6304125734>, 435.35056 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
