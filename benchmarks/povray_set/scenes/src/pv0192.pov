// validation scene pv0192 (seed 192)
#version 3.7;
#declare NS = 1;
#declare NLT = 81;
#declare LINES = array[81] { 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107 };
#declare LR = 1209.7145368166873;  // line rate, Hz
#declare TAU = 4.8457493617146155e-05;  // exposure, s
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
// film: 3056 x 4 samples spanning y/z in [-0.0624693075, 0.08683650172] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 15.58591096, 1279.253641>
  right <0, 191, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 23504.915
  pigment { function { max(0.002, min(0.98, 0.0101859 * (1 + 0.135457 * ((y / 23504.915) - 0.01218359711) / 0.07465290461 + 0.0592633 * sin(20.389419 * ((y / 23504.915) - 0.01218359711) / 0.07465290461 + 4.01511)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -182.6487312, 5552.96475> + 166589 * <0.2209701554, -0.5450458834, -0.8087627436> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, -182.6487312, 5552.96475>;  // mm
#declare V_0 = <2914.581717, -88.94818915, 789.3460967>;  // mm/s
#declare TC_0 = 0.0619980976647262;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.6440084823, 0.6440084823, 0.6440084823>] [0.925 rgb <0.6440084823, 0.6440084823, 0.6440084823>] [0.935 rgb <0.035000461, 0.035000461, 0.035000461>] [1.0 rgb <0.035000461, 0.035000461, 0.035000461>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.1055 diffuse 0.8945 } }
  no_shadow
  rotate <312.5843881, 163.1894199, 343.7914379>
  transform { Axis_Rotate_Trans(<-0.3049660091, 0.08252413404, -0.9487810604>, 1295.5096 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
