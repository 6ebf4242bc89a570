// validation scene pv0173 (seed 173)
#version 3.7;
#declare NS = 2;
#declare NLT = 83;
#declare LINES = array[83] { 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105 };
#declare LR = 22.83189178572881;  // line rate, Hz
#declare TAU = 0.020133767851901196;  // exposure, s
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
// film: 1936 x 4 samples spanning y/z in [-0.01178559032, 0.03000164874] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 26.37339913, 2895.620833>
  right <0, 121, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 23772.651
  pigment { function { max(0.002, min(0.98, 0.28956 * (1 + 0.122825 * ((y / 23772.651) - 0.00910802921) / 0.02089361953 + 0.194798 * sin(8.1456692 * ((y / 23772.651) - 0.00910802921) / 0.02089361953 + 0.35317)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 96.92166199, 8330.495678> + 249915 * <0.8723557285, -0.4425910144, -0.2076262917> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, 96.92166199, 8330.495678>;  // mm
#declare V_0 = <64.09223895, 22.61589148, 4.180924022>;  // mm/s
#declare TC_0 = 2.8030966772540293;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.7487037688, 0.7487037688, 0.7487037688>] [0.925 rgb <0.7487037688, 0.7487037688, 0.7487037688>] [0.935 rgb <0.04069042222, 0.04069042222, 0.04069042222>] [1.0 rgb <0.04069042222, 0.04069042222, 0.04069042222>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.3596 diffuse 0.6404 } }
  no_shadow
  rotate <84.65972761, 123.9581331, 144.4429158>
  transform { Axis_Rotate_Trans(<-0.4004294429, -0.6218295476, 0.6730410648>, 37.637677 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
