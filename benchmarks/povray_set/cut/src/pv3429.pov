// validation scene pv3429 (seed 3429)
#version 3.7;
#declare NS = 1;
#declare NLT = 172;
#declare LINES = array[172] { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171 };
#declare LR = 132642.4499360935;  // line rate, Hz
#declare TAU = 6.856791031639131e-06;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.159301 * sin(628.3185307 * T + 1.98476));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 1328 x 4 samples spanning y/z in [-0.0180475062, 0.01705923161] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -1.168281186, 2364.284571>
  right <0, 83.00231854, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 29825.483
  pigment { function { max(0.002, min(0.98, 0.0315761 * (1 + 0.15687 * ((y / 29825.483) - -0.0004941372963) / 0.0175533689 + 0.178845 * sin(6.4517493 * ((y / 29825.483) - -0.0004941372963) / 0.0175533689 + 1.65345)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -27.7544202, 5864.696418> + 175941 * <-0.1854125438, 0.3223390542, -0.9282885988> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, -27.7544202, 5864.696418>;  // mm
#declare V_0 = <36788.64805, -2572.148064, 403.8115592>;  // mm/s
#declare TC_0 = 0.0003317188428078567;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.8777300641, 0.8777300641, 0.8586489757>] [0.44 rgb <0.8777300641, 0.8777300641, 0.8586489757>] [0.46 rgb <0.6678380922, 0.8109462549, 0.1431081626>] [1.00 rgb <0.6678380922, 0.8109462549, 0.1431081626>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.4175 diffuse 0.5825 phong 0.2949 phong_size 40 } }
  no_shadow
  rotate <352.3881124, 244.4149933, 275.9182074>
  transform { Axis_Rotate_Trans(<-0.2162624818, 0.03028141163, 0.9758655517>, 0 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
