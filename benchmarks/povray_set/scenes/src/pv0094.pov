// validation scene pv0094 (seed 94)
#version 3.7;
#declare NS = 2;
#declare NLT = 95;
#declare LINES = array[95] { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94 };
#declare LR = 1029.7863949572861;  // line rate, Hz
#declare TAU = 0.0006692512757609768;  // exposure, s
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
// film: 1312 x 4 samples spanning y/z in [-0.02774116693, 0.03604094751] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 5.336896859, 1286.03324>
  right <0, 82.02591933, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 15626.234
  pigment { function { max(0.002, min(0.98, 0.0129873 * (1 + -0.0992863 * ((y / 15626.234) - 0.004149890292) / 0.03189105722 + 0.1499 * sin(7.200472 * ((y / 15626.234) - 0.004149890292) / 0.03189105722 + 4.92312)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 58.41585386, 6006.098353> + 180183 * <-0.001251317272, -0.5379149545, -0.8429981827> color rgb FL }
light_source { <0, 58.41585386, 6006.098353> + 180183 * <-0.3733677917, -0.8069387522, -0.4576530808> color rgb FL * 0.5327 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, 58.41585386, 6006.098353>;  // mm
#declare V_0 = <2040.65818, 14.82979385, 16.34673407>;  // mm/s
#declare TC_0 = 0.03398763099938968;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.7623385928, 0.7623385928, 0.7623385928>] [0.925 rgb <0.7623385928, 0.7623385928, 0.7623385928>] [0.935 rgb <0.04143144526, 0.04143144526, 0.04143144526>] [1.0 rgb <0.04143144526, 0.04143144526, 0.04143144526>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.3936 diffuse 0.6064 } }
  no_shadow
  rotate <341.6279977, 160.0314929, 63.09088905>
  transform { Axis_Rotate_Trans(<-0.3595692232, -0.5265886673, 0.7703339206>, 0 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
