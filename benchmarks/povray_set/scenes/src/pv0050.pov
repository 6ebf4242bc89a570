// validation scene pv0050 (seed 50)
#version 3.7;
#declare NS = 2;
#declare NLT = 51;
#declare LINES = array[51] { 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63 };
#declare LR = 370.32905225746435;  // line rate, Hz
#declare TAU = 0.0007467075228239884;  // exposure, s
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
// film: 408 x 4 samples spanning y/z in [-0.05698217598, 0.05940136166] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 1.05921818, 875.6815861>
  right <0, 101.9149208, 0>
  up <1, 0, 0>
  aperture 15.957331 blur_samples 19 focal_point <0, 1.384488021, 1144.5901> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 3925.3735
  pigment { function { max(0.002, min(0.98, 0.237719 * (1 + -0.131661 * ((y / 3925.3735) - 0.001209592844) / 0.05819176882 + 0.0284661 * sin(12.063545 * ((y / 3925.3735) - 0.001209592844) / 0.05819176882 + 2.85894)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 6.025480516, 843.3273174> + 25299.8 * <-0.4516078549, -0.4890048605, -0.7462738049> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, 6.025480516, 843.3273174>;  // mm
#declare V_0 = <-596.2147477, -85.39325053, 29.11862245>;  // mm/s
#declare TC_0 = 0.10261144722067662;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.8898592781, 0.8700846275, 0.8107606756>] [0.5 rgb <0.8898592781, 0.8700846275, 0.8107606756>] [0.5 rgb <0.7415493985, 0.0790986025, 0.05932395188>] [1.0 rgb <0.7415493985, 0.0790986025, 0.05932395188>] } }
  finish { ambient 0.5418 diffuse 0.4582 phong 0.5714 phong_size 40 } }
  no_shadow
  rotate <157.7486231, 200.6865203, 207.5508822>
  transform { Axis_Rotate_Trans(<0.9542364666, 0.1318618006, 0.2684124276>, 0 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
