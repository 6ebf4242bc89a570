// validation scene pv1085_a030 (seed 1085)
#version 3.7;
#declare NS = 2;
#declare NLT = 43;
#declare LINES = array[43] { 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52 };
#declare LR = 21402.86993229502;  // line rate, Hz
#declare TAU = 1.2434771898144163e-05;  // exposure, s
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
// film: 368 x 4 samples spanning y/z in [-0.005648137191, 0.003857222923] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -8.666937425, 9678.78539>
  right <0, 92.00034059, 0>
  up <1, 0, 0>
  aperture 21.058978 blur_samples 19 focal_point <0, -19.03925145, 21262.047> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 63297.984
  pigment { function { max(0.002, min(0.98, 0.143751 * (1 + -0.285973 * ((y / 63297.984) - -0.0008954571339) / 0.004752680057 + 0.0816078 * sin(13.416837 * ((y / 63297.984) - -0.0008954571339) / 0.004752680057 + 2.58818)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 7.654054485, 14440.72592> + 433222 * <-0.3160828417, -0.4019323264, -0.8593846881> color rgb FL }
light_source { <0, 7.654054485, 14440.72592> + 433222 * <-0.196707481, 0.4225797364, -0.8847217265> color rgb FL * 0.459 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, 7.654054485, 14440.72592>;  // mm
#declare V_0 = <38151.07229, 3100.922921, -12937.28677>;  // mm/s
#declare TC_0 = 0.0014484038868648997;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.7865390963, 0.7865390963, 0.7694404203>] [0.44 rgb <0.7865390963, 0.7865390963, 0.7694404203>] [0.46 rgb <0.5984536602, 0.7266937303, 0.1282400701>] [1.00 rgb <0.5984536602, 0.7266937303, 0.1282400701>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.5148 diffuse 0.4852 phong 0.509 phong_size 40 } }
  no_shadow
  rotate <324.43902, 353.922046, 210.163649>
  transform { Axis_Rotate_Trans(<0.01146178709, 0.9833376157, 0.1814270126>, 13279.65 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
