// validation scene pv0076 (seed 76)
#version 3.7;
#declare NS = 1;
#declare NLT = 67;
#declare LINES = array[67] { 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85 };
#declare LR = 20.0;  // line rate, Hz
#declare TAU = 0.016957973665168068;  // exposure, s
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
// film: 428 x 4 samples spanning y/z in [0.06262473489, 0.1226554949] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 165.1235514, 1782.419545>
  right <0, 107, 0>
  up <1, 0, 0>
  aperture 67.921036 blur_samples 19 focal_point <0, 1027.813122, 11094.687> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 64956.76
  pigment { function { max(0.002, min(0.98, 0.745024 * (1 + 0.227142 * ((y / 64956.76) - 0.09264011492) / 0.03001538003 + 0.140072 * sin(6.7992498 * ((y / 64956.76) - 0.09264011492) / 0.03001538003 + 4.97196)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 1173.026637, 14820.46038> + 444614 * <-0.3251014021, -0.484535725, -0.8121171157> color rgb FL }
light_source { <0, 1173.026637, 14820.46038> + 444614 * <0.04631356715, -0.98794786, -0.147695902> color rgb FL * 0.2068 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, 1173.026637, 14820.46038>;  // mm
#declare V_0 = <-71.88024612, -12.864615, 3.862438287>;  // mm/s
#declare TC_0 = 2.6;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.1458765514, 0.1458765514, 0.1458765514>] [0.925 rgb <0.1458765514, 0.1458765514, 0.1458765514>] [0.935 rgb <0.007928073445, 0.007928073445, 0.007928073445>] [1.0 rgb <0.007928073445, 0.007928073445, 0.007928073445>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.4421 diffuse 0.5579 } }
  no_shadow
  rotate <299.0338401, 309.6384772, 329.4288507>
  transform { Axis_Rotate_Trans(<-0.008097326651, -0.8590284871, 0.5118637432>, 29.620216 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
