// validation scene pv1075_a030 (seed 1075)
#version 3.7;
#declare NS = 2;
#declare NLT = 73;
#declare LINES = array[73] { 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92 };
#declare LR = 20.0;  // line rate, Hz
#declare TAU = 0.012751304094346789;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.165989 * sin(628.3185307 * T + 5.28127));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 2000 x 4 samples spanning y/z in [0.1306476243, 0.1599112247] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 620.5636968, 4271.518138>
  right <0, 125, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 31483.055
  pigment { function { max(0.002, min(0.98, 0.109787 * (1 + -0.140004 * ((y / 31483.055) - 0.1452794245) / 0.01463180021 + 0.238243 * sin(19.104593 * ((y / 31483.055) - 0.1452794245) / 0.01463180021 + 5.36973)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 2042.518967, 14308.09037> + 429243 * <0.2447388179, 0.7412642021, -0.6250042349> color rgb FL }
light_source { <0, 2042.518967, 14308.09037> + 429243 * <0.839002733, -0.5137955539, -0.1791327519> color rgb FL * 0.4627 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, 2042.518967, 14308.09037>;  // mm
#declare V_0 = <-64.34648596, 10.17856999, -20.36911857>;  // mm/s
#declare TC_0 = 2.8;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.7620955289, 0.7620955289, 0.7620955289>] [0.925 rgb <0.7620955289, 0.7620955289, 0.7620955289>] [0.935 rgb <0.04141823527, 0.04141823527, 0.04141823527>] [1.0 rgb <0.04141823527, 0.04141823527, 0.04141823527>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.4008 diffuse 0.5992 phong 0.6912 phong_size 40 } }
  no_shadow
  rotate <227.0057088, 9.818118296, 234.9949349>
  transform { Axis_Rotate_Trans(<0.6547953728, -0.3112260884, -0.6887534695>, 35.386172 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
