// validation scene pv0039 (seed 39)
#version 3.7;
#declare NS = 3;
#declare NLT = 57;
#declare LINES = array[57] { 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70 };
#declare LR = 68.26252375280814;  // line rate, Hz
#declare TAU = 0.007188641391337873;  // exposure, s
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
// film: 416 x 4 samples spanning y/z in [-0.007586837838, 0.008288624921] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 2.29870013, 6550.99014>
  right <0, 104, 0>
  up <1, 0, 0>
  aperture 20.60842 blur_samples 19 focal_point <0, 2.047050822, 5833.823> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 37035.876
  pigment { function { max(0.002, min(0.98, 0.725865 * (1 + -0.362725 * ((y / 37035.876) - 0.0003508935414) / 0.00793773138 + 0.11299 * sin(16.302497 * ((y / 37035.876) - 0.0003508935414) / 0.00793773138 + 4.86374)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -13.54964121, 8040.09328> + 241203 * <0.5895342839, 0.2640335751, -0.7633712068> color rgb FL }
light_source { <0, -13.54964121, 8040.09328> + 241203 * <-0.4850665565, 0.5738639735, -0.6598413261> color rgb FL * 0.2613 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, -13.54964121, 8040.09328>;  // mm
#declare V_0 = <97.91061347, 43.00322814, 30.93335744>;  // mm/s
#declare TC_0 = 0.6152717141266292;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.2385405636, 0.2332396622, 0.217336958>] [0.5 rgb <0.2385405636, 0.2332396622, 0.217336958>] [0.5 rgb <0.198783803, 0.02120360566, 0.01590270424>] [1.0 rgb <0.198783803, 0.02120360566, 0.01590270424>] } }
  finish { ambient 0.3009 diffuse 0.6991 phong 0.1 phong_size 40 } }
  no_shadow
  rotate <141.6282737, 146.5502334, 346.4119413>
  transform { Axis_Rotate_Trans(<0.4229351302, -0.8420703446, -0.3347288609>, 96.004398 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
