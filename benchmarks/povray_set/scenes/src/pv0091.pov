// validation scene pv0091 (seed 91)
#version 3.7;
#declare NS = 1;
#declare NLT = 87;
#declare LINES = array[87] { 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109 };
#declare LR = 1860.5420503327025;  // line rate, Hz
#declare TAU = 0.0003319245157883634;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.290852 * sin(628.3185307 * T + 4.5739));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 2336 x 4 samples spanning y/z in [-0.03308668572, 0.0225737135] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -13.78802493, 2623.049817>
  right <0, 146, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 71176.46
  pigment { function { max(0.002, min(0.98, 0.47514 * (1 + 0.194314 * ((y / 71176.46) - -0.005256486112) / 0.02783019961 + 0 * sin(12.487265 * ((y / 71176.46) - -0.005256486112) / 0.02783019961 + 4.46674)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -141.3196116, 14935.71125> + 448071 * <0.3213968623, -0.570902515, -0.755496112> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, -141.3196116, 14935.71125>;  // mm
#declare V_0 = <1657.272986, 106.64636, 861.7532687>;  // mm/s
#declare TC_0 = 0.035473533096549936;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.08340744024, 0.08340744024, 0.08159423502>] [0.44 rgb <0.08340744024, 0.08340744024, 0.08159423502>] [0.46 rgb <0.06346218279, 0.07706122196, 0.01359903917>] [1.00 rgb <0.06346218279, 0.07706122196, 0.01359903917>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.42 diffuse 0.58 phong 0.6537 phong_size 40 } }
  no_shadow
  rotate <348.517265, 65.51160403, 354.6203081>
  transform { Axis_Rotate_Trans(<0.1631237112, 0.9267072063, -0.338532729>, 0 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
