// validation scene pv0063 (seed 63)
#version 3.7;
#declare NS = 1;
#declare NLT = 88;
#declare LINES = array[88] { 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126 };
#declare LR = 83.722905814956;  // line rate, Hz
#declare TAU = 0.0027604928082381234;  // exposure, s
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
// film: 2560 x 4 samples spanning y/z in [-0.07279069391, 0.07527471638] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 1.342085866, 1080.574662>
  right <0, 159.9957307, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 12810.699
  pigment { function { max(0.002, min(0.98, 0.0935164 * (1 + 0.156195 * ((y / 12810.699) - 0.001242011231) / 0.07403270514 + 0 * sin(3.6387987 * ((y / 12810.699) - 0.001242011231) / 0.07403270514 + 2.77032)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 13.25824975, 4961.728249> + 148852 * <-0.7654401945, -0.6426933206, -0.03235126478> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, 13.25824975, 4961.728249>;  // mm
#declare V_0 = <-138.3774122, -68.76957056, 0.9994982386>;  // mm/s
#declare TC_0 = 1.301913722881422;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.8360703984, 0.8360703984, 0.8360703984>] [0.925 rgb <0.8360703984, 0.8360703984, 0.8360703984>] [0.935 rgb <0.04543860861, 0.04543860861, 0.04543860861>] [1.0 rgb <0.04543860861, 0.04543860861, 0.04543860861>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.1139 diffuse 0.8861 } }
  no_shadow
  rotate <131.8609183, 118.3410838, 209.1603392>
  transform { Axis_Rotate_Trans(<0.7042039904, 0.5291055201, -0.4734385794>, 60.990056 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
