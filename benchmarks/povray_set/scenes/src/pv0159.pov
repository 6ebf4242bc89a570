// validation scene pv0159 (seed 159)
#version 3.7;
#declare NS = 1;
#declare NLT = 169;
#declare LINES = array[169] { 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 216, 217, 218, 219, 220, 221, 222, 223, 224, 225, 226, 227, 228, 229, 230, 231, 232, 233, 234, 235, 236, 237, 238, 239, 240, 241, 242, 243, 244, 245, 246, 247, 248, 249, 250, 251, 252, 253, 254, 255, 256, 257, 258, 259, 260, 261, 262, 263, 264, 265, 266, 267, 268, 269, 270, 271, 272, 273, 274, 275, 276, 277, 278, 279, 280, 281, 282, 283, 284, 285, 286, 287 };
#declare LR = 2340.515543735412;  // line rate, Hz
#declare TAU = 0.00016279566978026852;  // exposure, s
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
// film: 1888 x 4 samples spanning y/z in [-0.06871757185, 0.07764476102] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 3.598631907, 806.2183601>
  right <0, 118, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 37605.277
  pigment { function { max(0.002, min(0.98, 0.138287 * (1 + -0.395158 * ((y / 37605.277) - 0.004463594586) / 0.07318116644 + 0.0734084 * sin(13.685847 * ((y / 37605.277) - 0.004463594586) / 0.07318116644 + 0.506956)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -225.845129, 7003.566049> + 210107 * <-0.4366678053, -0.220047451, -0.8722960204> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, -225.845129, 7003.566049>;  // mm
#declare V_0 = <5732.588475, 4299.187507, 2319.529251>;  // mm/s
#declare TC_0 = 0.048279961354007694;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.8444082409, 0.8444082409, 0.8444082409>] [0.925 rgb <0.8444082409, 0.8444082409, 0.8444082409>] [0.935 rgb <0.04589175222, 0.04589175222, 0.04589175222>] [1.0 rgb <0.04589175222, 0.04589175222, 0.04589175222>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.4934 diffuse 0.5066 phong 0.4369 phong_size 40 } }
  no_shadow
  rotate <287.7161036, 120.1064357, 240.3726291>
  transform { Axis_Rotate_Trans(<-0.550671502, 0.519327751, 0.6534979602>, 0 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
// ball 1: football
#declare C0_1 = <0, 272.0489944, 6749.320666>;  // mm
#declare V_1 = <7871.509128, 180.0581278, -128.8715132>;  // mm/s
#declare TC_1 = 0.10741589639121044;  // s
#declare P_1 = C0_1 + V_1 * (T - TC_1);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.8444082409, 0.8444082409, 0.8444082409>] [0.925 rgb <0.8444082409, 0.8444082409, 0.8444082409>] [0.935 rgb <0.04589175222, 0.04589175222, 0.04589175222>] [1.0 rgb <0.04589175222, 0.04589175222, 0.04589175222>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.4934 diffuse 0.5066 phong 0.4369 phong_size 40 } }
  no_shadow
  rotate <241.3281311, 319.6042945, 145.1201784>
  transform { Axis_Rotate_Trans(<-0.550671502, 0.519327751, 0.6534979602>, 0 * (T - TC_1)) }
  scale 110
  translate P_1 }
#end
