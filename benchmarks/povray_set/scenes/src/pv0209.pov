// validation scene pv0209 (seed 209)
#version 3.7;
#declare NS = 1;
#declare NLT = 107;
#declare LINES = array[107] { 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135 };
#declare LR = 128.77912690151243;  // line rate, Hz
#declare TAU = 0.0008444407379200187;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.307663 * sin(753.9822369 * T + 3.45815));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 1824 x 4 samples spanning y/z in [-0.02961556957, 0.06098481681] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 19.73553496, 1258.272779>
  right <0, 114, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 26449.956
  pigment { function { max(0.002, min(0.98, 0.0189966 * (1 + -0.0738007 * ((y / 26449.956) - 0.01568462362) / 0.04530019319 + 0.233407 * sin(5.6864736 * ((y / 26449.956) - 0.01568462362) / 0.04530019319 + 4.26661)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 175.5747322, 4964.721552> + 148942 * <-0.2598561052, -0.461358632, -0.8483059691> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, 175.5747322, 4964.721552>;  // mm
#declare V_0 = <-97.11442074, -9.810362647, 2.627417765>;  // mm/s
#declare TC_0 = 0.6367491531660397;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.7951977227, 0.7775266622, 0.7245134807>] [0.5 rgb <0.7951977227, 0.7775266622, 0.7245134807>] [0.5 rgb <0.6626647689, 0.07068424202, 0.05301318151>] [1.0 rgb <0.6626647689, 0.07068424202, 0.05301318151>] } }
  finish { ambient 0.1672 diffuse 0.8328 phong 0.1 phong_size 40 } }
  no_shadow
  rotate <117.4807689, 209.339395, 171.3624328>
  transform { Axis_Rotate_Trans(<0.07609515592, 0.2238058752, 0.9716586116>, 69.369271 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
