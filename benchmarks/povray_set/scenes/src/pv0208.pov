// validation scene pv0208 (seed 208)
#version 3.7;
#declare NS = 2;
#declare NLT = 47;
#declare LINES = array[47] { 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58 };
#declare LR = 20.0;  // line rate, Hz
#declare TAU = 0.013690610271989043;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.294491 * sin(753.9822369 * T + 3.76784));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 2560 x 4 samples spanning y/z in [-0.3836385188, -0.2635364057] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -431.0831228, 1332.199708>
  right <0, 160, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 22500.56
  pigment { function { max(0.002, min(0.98, 0.0736714 * (1 + 0.392505 * ((y / 22500.56) - -0.3235874622) / 0.06005105654 + 0.132876 * sin(13.56682 * ((y / 22500.56) - -0.3235874622) / 0.06005105654 + 5.22523)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -2772.457302, 7384.888393> + 221547 * <-0.9044639432, -0.1175039772, -0.4100460837> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, -2772.457302, 7384.888393>;  // mm
#declare V_0 = <106.1118991, 9.309859548, 19.38037244>;  // mm/s
#declare TC_0 = 1.75;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.7008098582, 0.7008098582, 0.7008098582>] [0.925 rgb <0.7008098582, 0.7008098582, 0.7008098582>] [0.935 rgb <0.03808749229, 0.03808749229, 0.03808749229>] [1.0 rgb <0.03808749229, 0.03808749229, 0.03808749229>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.1041 diffuse 0.8959 phong 0.7866 phong_size 40 } }
  no_shadow
  rotate <355.2658587, 300.9696583, 89.75760337>
  transform { Axis_Rotate_Trans(<-0.582732496, -0.7128766413, 0.3901662881>, 29.516172 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
