// validation scene pv3693 (seed 3693)
#version 3.7;
#declare NS = 2;
#declare NLT = 127;
#declare LINES = array[127] { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126 };
#declare LR = 92.81133060960731;  // line rate, Hz
#declare TAU = 0.006169455916229906;  // exposure, s
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
// film: 2400 x 4 samples spanning y/z in [-0.02168069504, 0.0378356945] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 20.35783705, 2520.314172>
  right <0, 150, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 42807.391
  pigment { function { max(0.002, min(0.98, 0.0428941 * (1 + -0.306022 * ((y / 42807.391) - 0.008077499734) / 0.02975819477 + 0.216515 * sin(20.04918 * ((y / 42807.391) - 0.008077499734) / 0.02975819477 + 2.3212)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 106.9328803, 9945.703229> + 298371 * <0.2016088834, 0.7848100636, -0.5860264688> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, 106.9328803, 9945.703229>;  // mm
#declare V_0 = <-134.1074165, 164.1784083, -12.17595122>;  // mm/s
#declare TC_0 = 0.5064036868267334;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.7028391048, 0.7028391048, 0.7028391048>] [0.925 rgb <0.7028391048, 0.7028391048, 0.7028391048>] [0.935 rgb <0.03819777743, 0.03819777743, 0.03819777743>] [1.0 rgb <0.03819777743, 0.03819777743, 0.03819777743>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.1379 diffuse 0.8621 phong 0.6599 phong_size 40 } }
  no_shadow
  rotate <331.4079879, 229.4419784, 101.8575175>
  transform { Axis_Rotate_Trans(<0.1322582684, -0.1193712086, -0.9840011509>, 22.910625 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
