// validation scene pv0020 (seed 20)
#version 3.7;
#declare NS = 2;
#declare NLT = 189;
#declare LINES = array[189] { 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214, 215, 216, 217, 218, 219, 220, 221, 222, 223, 224, 225, 226, 227, 228, 229, 230, 231, 232, 233, 234, 235, 236, 237, 238, 239, 240, 241, 242 };
#declare LR = 698.7744920597303;  // line rate, Hz
#declare TAU = 0.0009165936739804717;  // exposure, s
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
// film: 2192 x 4 samples spanning y/z in [0.1652276982, 0.207389481] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 605.3889356, 3249.388216>
  right <0, 137, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 48005.572
  pigment { function { max(0.002, min(0.98, 0.0381563 * (1 + 0.0726346 * ((y / 48005.572) - 0.1863085896) / 0.02108089137 + 0 * sin(10.152475 * ((y / 48005.572) - 0.1863085896) / 0.02108089137 + 4.74158)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 2594.070409, 14812.30845> + 444369 * <-0.2094025972, 0.04380309854, -0.9768479108> color rgb FL }
light_source { <0, 2594.070409, 14812.30845> + 444369 * <-0.7703804436, 0.5882622628, -0.2458891666> color rgb FL * 0.2871 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, 2594.070409, 14812.30845>;  // mm
#declare V_0 = <-1380.449261, 194.27126, 41.39237198>;  // mm/s
#declare TC_0 = 0.16171168421863474;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.8824841955, 0.8824841955, 0.8824841955>] [0.925 rgb <0.8824841955, 0.8824841955, 0.8824841955>] [0.935 rgb <0.04796109758, 0.04796109758, 0.04796109758>] [1.0 rgb <0.04796109758, 0.04796109758, 0.04796109758>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.1023 diffuse 0.8977 } }
  no_shadow
  rotate <341.6554018, 45.05155204, 347.9563483>
  transform { Axis_Rotate_Trans(<0.1838357699, -0.05923122115, 0.9811707661>, 58.510098 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
// ball 1: football
#declare C0_1 = <0, 2963.07489, 14962.29477>;  // mm
#declare V_1 = <-1302.734028, -176.5874564, -2.276716279>;  // mm/s
#declare TC_1 = 0.25720417766160947;  // s
#declare P_1 = C0_1 + V_1 * (T - TC_1);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.8824841955, 0.8824841955, 0.8824841955>] [0.925 rgb <0.8824841955, 0.8824841955, 0.8824841955>] [0.935 rgb <0.04796109758, 0.04796109758, 0.04796109758>] [1.0 rgb <0.04796109758, 0.04796109758, 0.04796109758>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.1023 diffuse 0.8977 } }
  no_shadow
  rotate <252.540617, 159.1729627, 131.8185919>
  transform { Axis_Rotate_Trans(<0.1838357699, -0.05923122115, 0.9811707661>, 58.510098 * (T - TC_1)) }
  scale 110
  translate P_1 }
#end
