// validation scene pv0184 (seed 184)
#version 3.7;
#declare NS = 1;
#declare NLT = 69;
#declare LINES = array[69] { 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86 };
#declare LR = 584.0376897674705;  // line rate, Hz
#declare TAU = 0.0006621369004838768;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.150709 * sin(628.3185307 * T + 2.95598));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 548 x 4 samples spanning y/z in [-0.05415350378, 0.04761894291] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -4.397141613, 1345.810897>
  right <0, 136.9664677, 0>
  up <1, 0, 0>
  aperture 94.196551 blur_samples 19 focal_point <0, -20.74942595, 6350.6719> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 40557.596
  pigment { function { max(0.002, min(0.98, 0.134022 * (1 + -0.128611 * ((y / 40557.596) - -0.003267280436) / 0.05088622335 + 0.0178635 * sin(13.407904 * ((y / 40557.596) - -0.003267280436) / 0.05088622335 + 5.99605)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 325.106774, 10053.86246> + 301616 * <0.3276416982, 0.2411127863, -0.913518222> color rgb FL }
light_source { <0, 325.106774, 10053.86246> + 301616 * <0.4494951714, 0.8417027671, 0.2991496996> color rgb FL * 0.2938 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, 325.106774, 10053.86246>;  // mm
#declare V_0 = <2081.698383, 329.6772685, 815.6936834>;  // mm/s
#declare TC_0 = 0.08903534979172893;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.889634152, 0.889634152, 0.889634152>] [0.925 rgb <0.889634152, 0.889634152, 0.889634152>] [0.935 rgb <0.04834968217, 0.04834968217, 0.04834968217>] [1.0 rgb <0.04834968217, 0.04834968217, 0.04834968217>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.1693 diffuse 0.8307 } }
  no_shadow
  rotate <332.2105826, 69.44633853, 121.1338934>
  transform { Axis_Rotate_Trans(<-0.7405153177, 0.334144192, 0.5830820895>, 1641.279 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
