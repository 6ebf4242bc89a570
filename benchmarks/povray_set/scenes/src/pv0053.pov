// validation scene pv0053 (seed 53)
#version 3.7;
#declare NS = 1;
#declare NLT = 67;
#declare LINES = array[67] { 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84 };
#declare LR = 5270.099073446299;  // line rate, Hz
#declare TAU = 7.071727974577131e-06;  // exposure, s
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
// film: 332 x 4 samples spanning y/z in [-0.01455274727, 0.01721086939] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 3.472906414, 2613.052566>
  right <0, 83, 0>
  up <1, 0, 0>
  aperture 73.431769 blur_samples 19 focal_point <0, 20.10203281, 15124.988> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 23827.399
  pigment { function { max(0.002, min(0.98, 0.0172227 * (1 + -0.0947793 * ((y / 23827.399) - 0.00132906106) / 0.01588180833 + 0.0707576 * sin(21.173059 * ((y / 23827.399) - 0.00132906106) / 0.01588180833 + 0.047465)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 64.97005331, 10474.64476> + 314239 * <-0.3012493948, -0.5301782902, -0.7925653176> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, 64.97005331, 10474.64476>;  // mm
#declare V_0 = <6440.095666, -8945.103383, -1325.735511>;  // mm/s
#declare TC_0 = 0.009677237427464402;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.7822519216, 0.7648685455, 0.7127184174>] [0.5 rgb <0.7822519216, 0.7648685455, 0.7127184174>] [0.5 rgb <0.6518766013, 0.06953350414, 0.0521501281>] [1.0 rgb <0.6518766013, 0.06953350414, 0.0521501281>] } }
  finish { ambient 0.1363 diffuse 0.8637 phong 0.1 phong_size 40 } }
  no_shadow
  rotate <48.05853155, 290.8128483, 212.3012986>
  transform { Axis_Rotate_Trans(<-0.8320369729, 0.2963971551, -0.4688957263>, 0 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
