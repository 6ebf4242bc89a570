// validation scene pv0051 (seed 51)
#version 3.7;
#declare NS = 1;
#declare NLT = 85;
#declare LINES = array[85] { 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121 };
#declare LR = 2331.370563894753;  // line rate, Hz
#declare TAU = 2.974972787307503e-05;  // exposure, s
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
// film: 1024 x 4 samples spanning y/z in [-0.1873864393, -0.1739964019] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -863.6459041, 4779.672998>
  right <0, 64, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 34045.493
  pigment { function { max(0.002, min(0.98, 0.0559513 * (1 + -0.0945863 * ((y / 34045.493) - -0.1806914206) / 0.006695018678 + 0 * sin(20.812681 * ((y / 34045.493) - -0.1806914206) / 0.006695018678 + 2.91539)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -1973.404523, 11017.16822> + 330515 * <-0.1681727637, 0.7417861503, -0.6492081552> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, -1973.404523, 11017.16822>;  // mm
#declare V_0 = <1368.264942, 180.0276787, 138.5878053>;  // mm/s
#declare TC_0 = 0.04418002079769324;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.6798841048, 0.6647755692, 0.6194499622>] [0.5 rgb <0.6798841048, 0.6647755692, 0.6194499622>] [0.5 rgb <0.5665700873, 0.06043414265, 0.04532560699>] [1.0 rgb <0.5665700873, 0.06043414265, 0.04532560699>] } }
  finish { ambient 0.4737 diffuse 0.5263 phong 0.2379 phong_size 40 } }
  no_shadow
  rotate <268.0017516, 7.739265582, 229.6351196>
  transform { Axis_Rotate_Trans(<0.6805894726, -0.6226911832, 0.3860746821>, 435.32555 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
