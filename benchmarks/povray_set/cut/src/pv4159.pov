// validation scene pv4159 (seed 4159)
#version 3.7;
#declare NS = 1;
#declare NLT = 101;
#declare LINES = array[101] { 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129 };
#declare LR = 27489.978398414896;  // line rate, Hz
#declare TAU = 2.082079464333493e-05;  // exposure, s
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
// film: 1744 x 4 samples spanning y/z in [-0.01017912071, 0.01382089495] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 8.269953062, 4541.716486>
  right <0, 109.0012668, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 32342.06
  pigment { function { max(0.002, min(0.98, 0.504526 * (1 + 0.1423 * ((y / 32342.06) - 0.001820887122) / 0.01200000783 + 0 * sin(17.374816 * ((y / 32342.06) - 0.001820887122) / 0.01200000783 + 6.0268)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -68.54556479, 7832.314488> + 234969 * <-0.6558895209, -0.2815457007, -0.7003862897> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, -68.54556479, 7832.314488>;  // mm
#declare V_0 = <19409.09967, -2240.911687, -2561.165011>;  // mm/s
#declare TC_0 = 0.0028737745390354772;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.1209389836, 0.1209389836, 0.1183098752>] [0.44 rgb <0.1209389836, 0.1209389836, 0.1183098752>] [0.46 rgb <0.09201879185, 0.1117371044, 0.01971831254>] [1.00 rgb <0.09201879185, 0.1117371044, 0.01971831254>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.4076 diffuse 0.5924 phong 0.3893 phong_size 40 } }
  no_shadow
  rotate <176.5109125, 132.4640224, 295.0479492>
  transform { Axis_Rotate_Trans(<-0.430851895, -0.5907298408, 0.6822059071>, 0 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
