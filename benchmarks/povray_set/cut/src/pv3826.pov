// validation scene pv3826 (seed 3826)
#version 3.7;
#declare NS = 1;
#declare NLT = 97;
#declare LINES = array[97] { 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123 };
#declare LR = 1111.3606573065713;  // line rate, Hz
#declare TAU = 0.00022822580795887705;  // exposure, s
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
// film: 2064 x 4 samples spanning y/z in [-0.02395801658, 0.02272546797] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -1.703159343, 2763.638419>
  right <0, 129.0162714, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 41134.518
  pigment { function { max(0.002, min(0.98, 0.053052 * (1 + 0.251608 * ((y / 41134.518) - -0.0006162743042) / 0.02334174227 + 0 * sin(8.3227508 * ((y / 41134.518) - -0.0006162743042) / 0.02334174227 + 5.71326)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 208.28713, 9804.06985> + 294122 * <0.4940849859, -0.2606606556, -0.8294191035> color rgb FL }
light_source { <0, 208.28713, 9804.06985> + 294122 * <0.5318752299, -0.6511483227, -0.5414005926> color rgb FL * 0.2301 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, 208.28713, 9804.06985>;  // mm
#declare V_0 = <921.4820325, 23.4653216, 412.6439365>;  // mm/s
#declare TC_0 = 0.06748484347265415;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.702243535, 0.6866381231, 0.6398218874>] [0.5 rgb <0.702243535, 0.6866381231, 0.6398218874>] [0.5 rgb <0.5852029458, 0.06242164755, 0.04681623566>] [1.0 rgb <0.5852029458, 0.06242164755, 0.04681623566>] } }
  finish { ambient 0.3129 diffuse 0.6871 phong 0.2331 phong_size 40 } }
  no_shadow
  rotate <77.33921663, 44.62119204, 116.1782015>
  transform { Axis_Rotate_Trans(<-0.5977186465, -0.5048619981, 0.62277346>, 537.6041 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
