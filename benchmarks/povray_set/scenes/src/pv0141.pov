// validation scene pv0141 (seed 141)
#version 3.7;
#declare NS = 1;
#declare NLT = 47;
#declare LINES = array[47] { 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58 };
#declare LR = 502.4278946913127;  // line rate, Hz
#declare TAU = 0.00013137660338674836;  // exposure, s
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
// film: 2160 x 4 samples spanning y/z in [-0.007882127106, 0.008873912944] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 3.99527102, 8056.721254>
  right <0, 134.998744, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 38124.09
  pigment { function { max(0.002, min(0.98, 0.032827 * (1 + -0.174574 * ((y / 38124.09) - 0.000495892919) / 0.008378020025 + 0 * sin(4.6319125 * ((y / 38124.09) - 0.000495892919) / 0.008378020025 + 0.194499)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -53.09294708, 12534.84923> + 376045 * <0.3008072618, 0.4321281765, -0.8501648254> color rgb FL }
light_source { <0, -53.09294708, 12534.84923> + 376045 * <0.5367921637, -0.1503972076, -0.8302016941> color rgb FL * 0.6544 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, -53.09294708, 12534.84923>;  // mm
#declare V_0 = <1474.314371, 223.1346558, 54.56093234>;  // mm/s
#declare TC_0 = 0.05174871911913683;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.8226543983, 0.8043731895, 0.7495295629>] [0.5 rgb <0.8226543983, 0.8043731895, 0.7495295629>] [0.5 rgb <0.6855453319, 0.07312483541, 0.05484362655>] [1.0 rgb <0.6855453319, 0.07312483541, 0.05484362655>] } }
  finish { ambient 0.2976 diffuse 0.7024 phong 0.4021 phong_size 40 } }
  no_shadow
  rotate <17.36702131, 46.84212164, 306.0694855>
  transform { Axis_Rotate_Trans(<0.2222065853, 0.9695482711, -0.1029581633>, 936.58518 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
// ball 1: baseball
#declare C0_1 = <0, 60.6577863, 13359.40858>;  // mm
#declare V_1 = <1015.419628, 385.8318333, 101.0896153>;  // mm/s
#declare TC_1 = 0.07609843301580987;  // s
#declare P_1 = C0_1 + V_1 * (T - TC_1);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.8226543983, 0.8043731895, 0.7495295629>] [0.5 rgb <0.8226543983, 0.8043731895, 0.7495295629>] [0.5 rgb <0.6855453319, 0.07312483541, 0.05484362655>] [1.0 rgb <0.6855453319, 0.07312483541, 0.05484362655>] } }
  finish { ambient 0.2976 diffuse 0.7024 phong 0.4021 phong_size 40 } }
  no_shadow
  rotate <16.42409134, 76.80607597, 321.5882979>
  transform { Axis_Rotate_Trans(<0.2222065853, 0.9695482711, -0.1029581633>, 936.58518 * (T - TC_1)) }
  scale 36.6
  translate P_1 }
#end
