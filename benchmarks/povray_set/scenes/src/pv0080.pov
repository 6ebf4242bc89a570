// validation scene pv0080 (seed 80)
#version 3.7;
#declare NS = 1;
#declare NLT = 62;
#declare LINES = array[62] { 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77 };
#declare LR = 280.33375859254;  // line rate, Hz
#declare TAU = 0.00013472640243797208;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.277592 * sin(753.9822369 * T + 3.28992));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 2912 x 4 samples spanning y/z in [-0.05992761225, 0.07966679982] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 12.86693844, 1303.694836>
  right <0, 181.9885141, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 29803.808
  pigment { function { max(0.002, min(0.98, 0.795569 * (1 + 0.289281 * ((y / 29803.808) - 0.009869593782) / 0.06979720604 + 0 * sin(6.7150175 * ((y / 29803.808) - 0.009869593782) / 0.06979720604 + 5.30332)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -182.4019009, 5199.274253> + 155978 * <-0.1481896596, -0.1666343648, -0.9748193747> color rgb FL }
light_source { <0, -182.4019009, 5199.274253> + 155978 * <-0.7384946816, -0.628958189, 0.2429757224> color rgb FL * 0.6757 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, -182.4019009, 5199.274253>;  // mm
#declare V_0 = <1721.913595, 71.60059758, 305.5692639>;  // mm/s
#declare TC_0 = 0.12841835453833209;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.1992288074, 0.1992288074, 0.1992288074>] [0.925 rgb <0.1992288074, 0.1992288074, 0.1992288074>] [0.935 rgb <0.01082765258, 0.01082765258, 0.01082765258>] [1.0 rgb <0.01082765258, 0.01082765258, 0.01082765258>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.5422 diffuse 0.4578 } }
  no_shadow
  rotate <329.6612348, 134.8079216, 85.65572194>
  transform { Axis_Rotate_Trans(<-0.2559771073, 0.9101802267, 0.3256496207>, 0 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
// ball 1: football
#declare C0_1 = <0, 219.5024082, 4580.641513>;  // mm
#declare V_1 = <1488.223908, -17.98906898, 19.12312097>;  // mm/s
#declare TC_1 = 0.19461997717842466;  // s
#declare P_1 = C0_1 + V_1 * (T - TC_1);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.1992288074, 0.1992288074, 0.1992288074>] [0.925 rgb <0.1992288074, 0.1992288074, 0.1992288074>] [0.935 rgb <0.01082765258, 0.01082765258, 0.01082765258>] [1.0 rgb <0.01082765258, 0.01082765258, 0.01082765258>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.5422 diffuse 0.4578 } }
  no_shadow
  rotate <39.08799476, 159.8005817, 296.9628117>
  transform { Axis_Rotate_Trans(<-0.2559771073, 0.9101802267, 0.3256496207>, 0 * (T - TC_1)) }
  scale 110
  translate P_1 }
#end
