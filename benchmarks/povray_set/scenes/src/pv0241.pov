// validation scene pv0241 (seed 241)
#version 3.7;
#declare NS = 1;
#declare NLT = 131;
#declare LINES = array[131] { 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167 };
#declare LR = 1507.8600273277257;  // line rate, Hz
#declare TAU = 0.00017397979360413184;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.255241 * sin(753.9822369 * T + 5.7689));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 1712 x 4 samples spanning y/z in [-0.004598552928, 0.006202593283] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 7.945097428, 9906.356039>
  right <0, 107, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 50580.432
  pigment { function { max(0.002, min(0.98, 0.0762435 * (1 + 0.399766 * ((y / 50580.432) - 0.0008020201775) / 0.005400573106 + 0 * sin(24.472902 * ((y / 50580.432) - 0.0008020201775) / 0.005400573106 + 4.38391)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 35.45332003, 12830.10305> + 384903 * <0.02271596147, -0.6583264565, -0.7523897007> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, 35.45332003, 12830.10305>;  // mm
#declare V_0 = <884.9329167, -141.4483656, -52.46476554>;  // mm/s
#declare TC_0 = 0.06764553615813228;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.7548065024, 0.7380330246, 0.6877125911>] [0.5 rgb <0.7548065024, 0.7380330246, 0.6877125911>] [0.5 rgb <0.6290054187, 0.06709391132, 0.05032043349>] [1.0 rgb <0.6290054187, 0.06709391132, 0.05032043349>] } }
  finish { ambient 0.4335 diffuse 0.5665 phong 0.1 phong_size 40 } }
  no_shadow
  rotate <165.8368054, 62.85396332, 232.5410407>
  transform { Axis_Rotate_Trans(<-0.04712732738, -0.02130505365, 0.9986616593>, 0 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
