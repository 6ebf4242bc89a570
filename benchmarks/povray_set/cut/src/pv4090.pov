// validation scene pv4090 (seed 4090)
#version 3.7;
#declare NS = 1;
#declare NLT = 127;
#declare LINES = array[127] { 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162 };
#declare LR = 9052.974615833666;  // line rate, Hz
#declare TAU = 5.742003498140738e-06;  // exposure, s
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
// film: 2320 x 4 samples spanning y/z in [-0.03850705351, 0.02702424882] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -12.70390349, 2212.683021>
  right <0, 145, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 17283.489
  pigment { function { max(0.002, min(0.98, 0.123121 * (1 + -0.232308 * ((y / 17283.489) - -0.005741402348) / 0.03276565117 + 0 * sin(17.544669 * ((y / 17283.489) - -0.005741402348) / 0.03276565117 + 1.78206)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 204.4398432, 7916.901594> + 237507 * <-0.3986528967, -0.06181954371, -0.9150159627> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, 204.4398432, 7916.901594>;  // mm
#declare V_0 = <5166.877735, -624.8509655, -996.5242511>;  // mm/s
#declare TC_0 = 0.010935632121054317;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.8524641248, 0.8524641248, 0.833932296>] [0.44 rgb <0.8524641248, 0.8524641248, 0.833932296>] [0.46 rgb <0.648614008, 0.787602724, 0.138988716>] [1.00 rgb <0.648614008, 0.787602724, 0.138988716>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.4001 diffuse 0.5999 phong 0.3184 phong_size 40 } }
  no_shadow
  rotate <186.9520458, 125.2306587, 236.3230935>
  transform { Axis_Rotate_Trans(<-0.4979465485, -0.7957886108, 0.344629833>, 0 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
