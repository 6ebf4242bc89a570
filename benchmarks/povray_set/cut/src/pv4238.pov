// validation scene pv4238 (seed 4238)
#version 3.7;
#declare NS = 1;
#declare NLT = 87;
#declare LINES = array[87] { 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110 };
#declare LR = 20333.218320159016;  // line rate, Hz
#declare TAU = 1.0544239098266633e-05;  // exposure, s
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
// film: 1888 x 4 samples spanning y/z in [0.1763242046, 0.2244746121] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 477.6429581, 2383.454932>
  right <0, 114.7643261, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 24491.418
  pigment { function { max(0.002, min(0.98, 0.588915 * (1 + -0.208283 * ((y / 24491.418) - 0.2003994083) / 0.02407520373 + 0.116803 * sin(5.6369844 * ((y / 24491.418) - 0.2003994083) / 0.02407520373 + 5.2654)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 2008.845056, 8919.700493> + 267591 * <-0.2060047135, -0.05552637024, -0.9769743498> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, 2008.845056, 8919.700493>;  // mm
#declare V_0 = <-55028.54278, 2060.368576, -29992.41539>;  // mm/s
#declare TC_0 = 0.0032951006055728037;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.1781817047, 0.1781817047, 0.1781817047>] [0.925 rgb <0.1781817047, 0.1781817047, 0.1781817047>] [0.935 rgb <0.009683788301, 0.009683788301, 0.009683788301>] [1.0 rgb <0.009683788301, 0.009683788301, 0.009683788301>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.5649 diffuse 0.4351 phong 0.7306 phong_size 40 } }
  no_shadow
  rotate <252.728623, 174.155462, 73.86097512>
  transform { Axis_Rotate_Trans(<-0.252144546, -0.6618716328, 0.7059384319>, 10954.98 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
