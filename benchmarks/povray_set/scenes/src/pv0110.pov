// validation scene pv0110 (seed 110)
#version 3.7;
#declare NS = 1;
#declare NLT = 81;
#declare LINES = array[81] { 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103 };
#declare LR = 61.56780192306954;  // line rate, Hz
#declare TAU = 0.0036686681017454666;  // exposure, s
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
// film: 1696 x 4 samples spanning y/z in [-0.02648232746, 0.01801360166] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -10.08727037, 2382.2404>
  right <0, 106, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 63294.849
  pigment { function { max(0.002, min(0.98, 0.642735 * (1 + -0.267121 * ((y / 63294.849) - -0.004234362899) / 0.02224796456 + 0.0441302 * sin(24.580185 * ((y / 63294.849) - -0.004234362899) / 0.02224796456 + 4.80504)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 18.82010861, 11574.19978> + 347226 * <-0.4360661719, 0.5802338328, -0.6878771641> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, 18.82010861, 11574.19978>;  // mm
#declare V_0 = <-178.7603102, -70.17066811, 71.47818629>;  // mm/s
#declare TC_0 = 1.0232621278037508;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.1389319902, 0.1389319902, 0.1389319902>] [0.925 rgb <0.1389319902, 0.1389319902, 0.1389319902>] [0.935 rgb <0.007550651641, 0.007550651641, 0.007550651641>] [1.0 rgb <0.007550651641, 0.007550651641, 0.007550651641>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.5579 diffuse 0.4421 phong 0.6043 phong_size 40 } }
  no_shadow
  rotate <24.28772877, 113.9407548, 262.8906668>
  transform { Axis_Rotate_Trans(<-0.3181606921, -0.5524099495, 0.7704654579>, 0 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
