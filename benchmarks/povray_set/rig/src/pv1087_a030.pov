// validation scene pv1087_a030 (seed 1087)
#version 3.7;
#declare NS = 1;
#declare NLT = 41;
#declare LINES = array[41] { 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51 };
#declare LR = 918.4905331646216;  // line rate, Hz
#declare TAU = 0.00015216483432339983;  // exposure, s
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
// film: 1184 x 4 samples spanning y/z in [0.2604924958, 0.3402732806] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 278.6176369, 927.5416404>
  right <0, 74, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 58018.546
  pigment { function { max(0.002, min(0.98, 0.721221 * (1 + 0.315689 * ((y / 58018.546) - 0.3003828882) / 0.0398903924 + 0 * sin(15.016798 * ((y / 58018.546) - 0.3003828882) / 0.0398903924 + 0.0492506)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 4143.129919, 13525.29946> + 405759 * <-0.2293461399, 0.101837399, -0.9680028369> color rgb FL }
light_source { <0, 4143.129919, 13525.29946> + 405759 * <0.5436143376, -0.3881866084, -0.7441737761> color rgb FL * 0.6318 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, 4143.129919, 13525.29946>;  // mm
#declare V_0 = <-5735.033462, -1510.163786, -50.04726501>;  // mm/s
#declare TC_0 = 0.03375102832382035;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.2105743253, 0.2105743253, 0.2105743253>] [0.925 rgb <0.2105743253, 0.2105743253, 0.2105743253>] [0.935 rgb <0.01144425681, 0.01144425681, 0.01144425681>] [1.0 rgb <0.01144425681, 0.01144425681, 0.01144425681>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.5168 diffuse 0.4832 phong 0.3719 phong_size 40 } }
  no_shadow
  rotate <66.43099453, 78.54122263, 290.6311812>
  transform { Axis_Rotate_Trans(<-0.3560194654, 0.5135868536, -0.7806911579>, 0 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
