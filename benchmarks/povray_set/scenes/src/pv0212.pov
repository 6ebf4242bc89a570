// validation scene pv0212 (seed 212)
#version 3.7;
#declare NS = 1;
#declare NLT = 43;
#declare LINES = array[43] { 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56 };
#declare LR = 239.7234043281333;  // line rate, Hz
#declare TAU = 0.0020823064181800304;  // exposure, s
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
// film: 1648 x 4 samples spanning y/z in [0.1784151445, 0.2711217277] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 254.0118966, 1130.104836>
  right <0, 104.7681581, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 10432.356
  pigment { function { max(0.002, min(0.98, 0.539064 * (1 + 0.389471 * ((y / 10432.356) - 0.2247684361) / 0.04635329162 + 0.247093 * sin(17.383532 * ((y / 10432.356) - 0.2247684361) / 0.04635329162 + 3.10495)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 1007.058693, 4570.702931> + 137121 * <-0.07691316791, -0.05984445718, -0.9952401748> color rgb FL }
light_source { <0, 1007.058693, 4570.702931> + 137121 * <0.607964452, 0.5638148215, -0.5590099035> color rgb FL * 0.58 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, 1007.058693, 4570.702931>;  // mm
#declare V_0 = <356.6581985, 57.52004502, -9.814122164>;  // mm/s
#declare TC_0 = 0.17520191704982804;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.1770096265, 0.1730760792, 0.1612754375>] [0.5 rgb <0.1770096265, 0.1730760792, 0.1612754375>] [0.5 rgb <0.1475080221, 0.01573418902, 0.01180064177>] [1.0 rgb <0.1475080221, 0.01573418902, 0.01180064177>] } }
  finish { ambient 0.5285 diffuse 0.4715 phong 0.1 phong_size 40 } }
  no_shadow
  rotate <187.2082742, 69.55196042, 132.8718153>
  transform { Axis_Rotate_Trans(<-0.1397154515, -0.3149352056, 0.9387733533>, 80.961926 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
