// validation scene pv0133 (seed 133)
#version 3.7;
#declare NS = 2;
#declare NLT = 29;
#declare LINES = array[29] { 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35 };
#declare LR = 521.8569522442311;  // line rate, Hz
#declare TAU = 0.0002067767967899459;  // exposure, s
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
// film: 2576 x 4 samples spanning y/z in [0.07193218382, 0.1152955347] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 347.5707256, 3712.8127>
  right <0, 161, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 22607.536
  pigment { function { max(0.002, min(0.98, 0.66289 * (1 + -0.28575 * ((y / 22607.536) - 0.09361385928) / 0.02168167546 + 0.172992 * sin(25.017603 * ((y / 22607.536) - 0.09361385928) / 0.02168167546 + 3.57374)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 367.7022579, 4256.501073> + 127695 * <-0.1949162165, -0.1544153122, -0.9685884471> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, 367.7022579, 4256.501073>;  // mm
#declare V_0 = <1415.448455, 377.0935593, 293.1721488>;  // mm/s
#declare TC_0 = 0.04024091259049073;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.156416809, 0.156416809, 0.1530164436>] [0.44 rgb <0.156416809, 0.156416809, 0.1530164436>] [0.46 rgb <0.1190127894, 0.14451553, 0.0255027406>] [1.00 rgb <0.1190127894, 0.14451553, 0.0255027406>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.4822 diffuse 0.5178 } }
  no_shadow
  rotate <82.21247283, 141.5194227, 344.8355874>
  transform { Axis_Rotate_Trans(<0.8372929748, 0.4542577632, 0.3042866394>, 1073.2224 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
