// validation scene pv0137 (seed 137)
#version 3.7;
#declare NS = 1;
#declare NLT = 35;
#declare LINES = array[35] { 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43 };
#declare LR = 849.7713915718433;  // line rate, Hz
#declare TAU = 0.00013900741364906646;  // exposure, s
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
// film: 2736 x 4 samples spanning y/z in [-0.03300085223, 0.02224683859] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -16.64265334, 3095.151986>
  right <0, 171, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 25871.135
  pigment { function { max(0.002, min(0.98, 0.226883 * (1 + -0.206397 * ((y / 25871.135) - -0.00537700682) / 0.02762384541 + 0 * sin(19.395597 * ((y / 25871.135) - -0.00537700682) / 0.02762384541 + 0.575891)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 31.52271177, 5713.487454> + 171405 * <-0.9712657291, -0.08074205477, -0.2238830142> color rgb FL }
light_source { <0, 31.52271177, 5713.487454> + 171405 * <0.1913153878, 0.1623007574, -0.9680169867> color rgb FL * 0.2259 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, 31.52271177, 5713.487454>;  // mm
#declare V_0 = <-1867.672238, 547.5996533, 167.1945857>;  // mm/s
#declare TC_0 = 0.030596464246586547;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.733857482, 0.733857482, 0.7179040584>] [0.44 rgb <0.733857482, 0.733857482, 0.7179040584>] [0.46 rgb <0.5583698232, 0.6780204996, 0.1196506764>] [1.00 rgb <0.5583698232, 0.6780204996, 0.1196506764>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.1754 diffuse 0.8246 phong 0.2646 phong_size 40 } }
  no_shadow
  rotate <200.7070625, 346.1260067, 285.1073179>
  transform { Axis_Rotate_Trans(<-0.8592687776, -0.4291293612, 0.2783974842>, 0 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
