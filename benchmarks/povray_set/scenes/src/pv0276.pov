// validation scene pv0276 (seed 276)
#version 3.7;
#declare NS = 1;
#declare NLT = 87;
#declare LINES = array[87] { 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110 };
#declare LR = 112.16747028693588;  // line rate, Hz
#declare TAU = 0.0004078632133168702;  // exposure, s
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
// film: 1728 x 4 samples spanning y/z in [-0.03784717142, 0.02920391099] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -6.960902741, 1610.712253>
  right <0, 108, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 67330.392
  pigment { function { max(0.002, min(0.98, 0.0382793 * (1 + -0.217274 * ((y / 67330.392) - -0.004321630216) / 0.0335255412 + 0.109648 * sin(17.477671 * ((y / 67330.392) - -0.004321630216) / 0.0335255412 + 5.45297)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -307.3667303, 11416.19381> + 342486 * <-0.3689379493, 0.6761950833, -0.6376872265> color rgb FL }
light_source { <0, -307.3667303, 11416.19381> + 342486 * <0.9148664534, -0.1920414339, -0.3551611749> color rgb FL * 0.2975 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, -307.3667303, 11416.19381>;  // mm
#declare V_0 = <108.40908, 16.56530991, 31.34654866>;  // mm/s
#declare TC_0 = 0.5973211290992578;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.6426520121, 0.6283708563, 0.5855273888>] [0.5 rgb <0.6426520121, 0.6283708563, 0.5855273888>] [0.5 rgb <0.5355433434, 0.0571246233, 0.04284346747>] [1.0 rgb <0.5355433434, 0.0571246233, 0.04284346747>] } }
  finish { ambient 0.5304 diffuse 0.4696 phong 0.6513 phong_size 40 } }
  no_shadow
  rotate <188.9462049, 305.3288165, 341.5498905>
  transform { Axis_Rotate_Trans(<-0.6122444496, -0.3490715231, -0.7094404878>, 95.198469 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
