// validation scene pv1071_a030 (seed 1071)
#version 3.7;
#declare NS = 1;
#declare NLT = 89;
#declare LINES = array[89] { 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112 };
#declare LR = 190.65129452597327;  // line rate, Hz
#declare TAU = 0.002117247086988271;  // exposure, s
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
// film: 3136 x 4 samples spanning y/z in [0.1726526779, 0.2055229428] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 1127.499609, 5962.836034>
  right <0, 196, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 21737.738
  pigment { function { max(0.002, min(0.98, 0.0351978 * (1 + 0.191613 * ((y / 21737.738) - 0.1890878103) / 0.01643513245 + 0.198506 * sin(15.678688 * ((y / 21737.738) - 0.1890878103) / 0.01643513245 + 4.19555)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 1959.118802, 10291.72667> + 308752 * <-0.7807892897, 0.5526265956, -0.2914994527> color rgb FL }
light_source { <0, 1959.118802, 10291.72667> + 308752 * <0.5317105099, 0.5216161607, 0.6672334783> color rgb FL * 0.5216 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, 1959.118802, 10291.72667>;  // mm
#declare V_0 = <-155.5116483, -10.66531572, 65.22765589>;  // mm/s
#declare TC_0 = 0.35667211266030013;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.8019551198, 0.8019551198, 0.7845213129>] [0.44 rgb <0.8019551198, 0.8019551198, 0.7845213129>] [0.46 rgb <0.6101832434, 0.7409367955, 0.1307535521>] [1.00 rgb <0.6101832434, 0.7409367955, 0.1307535521>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.5696 diffuse 0.4304 phong 0.6212 phong_size 40 } }
  no_shadow
  rotate <14.84607312, 257.9936323, 113.7010761>
  transform { Axis_Rotate_Trans(<-0.2578842291, 0.6605713711, 0.7050823981>, 0 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
