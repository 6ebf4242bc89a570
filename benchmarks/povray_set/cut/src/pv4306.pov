// validation scene pv4306 (seed 4306)
#version 3.7;
#declare NS = 1;
#declare NLT = 179;
#declare LINES = array[179] { 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214, 215, 216, 217, 218, 219, 220, 221, 222, 223, 224, 225, 226, 227, 228, 229, 230 };
#declare LR = 113050.02613583075;  // line rate, Hz
#declare TAU = 7.080932476135469e-06;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.261669 * sin(753.9822369 * T + 0.861319));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 1136 x 4 samples spanning y/z in [-0.01487076744, 0.01912300591] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 4.440775799, 2088.676741>
  right <0, 71.00200372, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 28542.903
  pigment { function { max(0.002, min(0.98, 0.0883064 * (1 + 0.320671 * ((y / 28542.903) - 0.002126119237) / 0.01699688667 + 0 * sin(10.915653 * ((y / 28542.903) - 0.002126119237) / 0.01699688667 + 2.3602)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 113.6664757, 6932.171171> + 207965 * <0.3675829705, -0.02116884779, -0.9297497726> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, 113.6664757, 6932.171171>;  // mm
#declare V_0 = <-49394.30188, 4305.962291, -2157.30449>;  // mm/s
#declare TC_0 = 0.0012472354480536525;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.8313252698, 0.8128513749, 0.7574296902>] [0.5 rgb <0.8313252698, 0.8128513749, 0.7574296902>] [0.5 rgb <0.6927710581, 0.07389557954, 0.05542168465>] [1.0 rgb <0.6927710581, 0.07389557954, 0.05542168465>] } }
  finish { ambient 0.1839 diffuse 0.8161 phong 0.1 phong_size 40 } }
  no_shadow
  rotate <191.1660613, 68.51830747, 317.2820813>
  transform { Axis_Rotate_Trans(<0.2603440267, 0.5169277296, -0.8154794357>, 0 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
