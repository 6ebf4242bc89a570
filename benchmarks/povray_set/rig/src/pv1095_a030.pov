// validation scene pv1095_a030 (seed 1095)
#version 3.7;
#declare NS = 1;
#declare NLT = 41;
#declare LINES = array[41] { 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50 };
#declare LR = 195.73686854481883;  // line rate, Hz
#declare TAU = 0.0034127989606451666;  // exposure, s
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
// film: 2592 x 4 samples spanning y/z in [-0.05900729459, 0.06802592742] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 5.750537123, 1275.256956>
  right <0, 162, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 31875.183
  pigment { function { max(0.002, min(0.98, 0.0345849 * (1 + -0.272675 * ((y / 31875.183) - 0.004509316413) / 0.063516611 + 0 * sin(18.86001 * ((y / 31875.183) - 0.004509316413) / 0.063516611 + 6.21458)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -396.9612084, 12691.35712> + 380741 * <0.734925964, 0.5306463994, -0.4222537463> color rgb FL }
light_source { <0, -396.9612084, 12691.35712> + 380741 * <-0.8083738597, -0.02042102, -0.5883151237> color rgb FL * 0.6647 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, -396.9612084, 12691.35712>;  // mm
#declare V_0 = <-419.2775299, 199.3753956, 398.477271>;  // mm/s
#declare TC_0 = 0.15326698655716336;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.770336037, 0.770336037, 0.7535896014>] [0.44 rgb <0.770336037, 0.770336037, 0.7535896014>] [0.46 rgb <0.5861252455, 0.7117235124, 0.1255982669>] [1.00 rgb <0.5861252455, 0.7117235124, 0.1255982669>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.1026 diffuse 0.8974 } }
  no_shadow
  rotate <38.16260836, 273.052644, 113.394496>
  transform { Axis_Rotate_Trans(<0.8533311582, 0.2025696452, -0.4804076116>, 0 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
