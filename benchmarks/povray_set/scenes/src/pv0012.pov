// validation scene pv0012 (seed 12)
#version 3.7;
#declare NS = 1;
#declare NLT = 67;
#declare LINES = array[67] { 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85 };
#declare LR = 16676.317207690616;  // line rate, Hz
#declare TAU = 2.726207857073657e-05;  // exposure, s
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
// film: 2560 x 4 samples spanning y/z in [-0.07747299438, 0.0745765089] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -1.523969714, 1052.28887>
  right <0, 160, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 31335.956
  pigment { function { max(0.002, min(0.98, 0.0383275 * (1 + -0.345753 * ((y / 31335.956) - -0.001448242737) / 0.07602475164 + 0 * sin(5.20403 * ((y / 31335.956) - -0.001448242737) / 0.07602475164 + 5.44668)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 465.8281711, 7911.313586> + 237339 * <-0.4108112203, -0.6414451372, -0.6479060713> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, 465.8281711, 7911.313586>;  // mm
#declare V_0 = <21211.61078, 14365.6493, -9963.887396>;  // mm/s
#declare TC_0 = 0.0031181944641841645;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.7829916345, 0.7655918204, 0.7133923781>] [0.5 rgb <0.7829916345, 0.7655918204, 0.7133923781>] [0.5 rgb <0.6524930288, 0.0695992564, 0.0521994423>] [1.0 rgb <0.6524930288, 0.0695992564, 0.0521994423>] } }
  finish { ambient 0.1883 diffuse 0.8117 phong 0.409 phong_size 40 } }
  no_shadow
  rotate <246.3774752, 213.6486085, 156.1504296>
  transform { Axis_Rotate_Trans(<0.05803410157, 0.4294058784, -0.9012450469>, 0 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
