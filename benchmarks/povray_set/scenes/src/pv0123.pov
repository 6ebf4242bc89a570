// validation scene pv0123 (seed 123)
#version 3.7;
#declare NS = 1;
#declare NLT = 123;
#declare LINES = array[123] { 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157 };
#declare LR = 12510.080782806903;  // line rate, Hz
#declare TAU = 2.7623072874732077e-06;  // exposure, s
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
// film: 1552 x 4 samples spanning y/z in [0.1990689081, 0.2142326416] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 1315.112055, 6363.934791>
  right <0, 96.50101124, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 15941.533
  pigment { function { max(0.002, min(0.98, 0.295242 * (1 + 0.284687 * ((y / 15941.533) - 0.2066507748) / 0.007581866754 + 0 * sin(4.1881646 * ((y / 15941.533) - 0.2066507748) / 0.007581866754 + 4.02884)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 1397.073176, 6708.067952> + 201242 * <-0.7586349082, -0.5415603549, -0.3621953314> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, 1397.073176, 6708.067952>;  // mm
#declare V_0 = <7815.727371, 532.0127552, -4300.348551>;  // mm/s
#declare TC_0 = 0.007673811357951948;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.6889146512, 0.6736054367, 0.6276777933>] [0.5 rgb <0.6889146512, 0.6736054367, 0.6276777933>] [0.5 rgb <0.5740955427, 0.06123685788, 0.04592764341>] [1.0 rgb <0.5740955427, 0.06123685788, 0.04592764341>] } }
  finish { ambient 0.2497 diffuse 0.7503 phong 0.3455 phong_size 40 } }
  no_shadow
  rotate <250.6441806, 160.3835659, 281.1045895>
  transform { Axis_Rotate_Trans(<0.1820734036, 0.5194857867, 0.8348555522>, 7908.114 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
