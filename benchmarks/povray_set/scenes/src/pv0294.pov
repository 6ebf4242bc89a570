// validation scene pv0294 (seed 294)
#version 3.7;
#declare NS = 1;
#declare NLT = 71;
#declare LINES = array[71] { 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89 };
#declare LR = 1027.7989828713628;  // line rate, Hz
#declare TAU = 9.399567902746953e-05;  // exposure, s
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
// film: 2272 x 4 samples spanning y/z in [-0.01302127826, 0.01918152956] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 13.58197845, 4409.553378>
  right <0, 142, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 64251.309
  pigment { function { max(0.002, min(0.98, 0.634125 * (1 + -0.0208804 * ((y / 64251.309) - 0.003080125648) / 0.01610140391 + 0 * sin(24.71579 * ((y / 64251.309) - 0.003080125648) / 0.01610140391 + 5.67875)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 15.63406768, 14610.57461> + 438317 * <0.619036073, 0.3034213027, -0.7243823945> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, 15.63406768, 14610.57461>;  // mm
#declare V_0 = <-3445.577493, 423.9798162, -340.8445157>;  // mm/s
#declare TC_0 = 0.05253945654736898;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.1445857132, 0.1445857132, 0.1445857132>] [0.925 rgb <0.1445857132, 0.1445857132, 0.1445857132>] [0.935 rgb <0.007857919196, 0.007857919196, 0.007857919196>] [1.0 rgb <0.007857919196, 0.007857919196, 0.007857919196>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.3315 diffuse 0.6685 } }
  no_shadow
  rotate <158.6492133, 340.7054287, 68.8037629>
  transform { Axis_Rotate_Trans(<-0.7135832574, -0.4627204258, -0.5260121123>, 1420.6872 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
