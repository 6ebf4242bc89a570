// validation scene pv0135 (seed 135)
#version 3.7;
#declare NS = 1;
#declare NLT = 171;
#declare LINES = array[171] { 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214, 215, 216, 217, 218, 219, 220, 221, 222, 223, 224, 225, 226, 227, 228, 229, 230, 231, 232, 233, 234, 235, 236, 237, 238, 239, 240, 241, 242, 243, 244, 245, 246, 247, 248, 249, 250, 251, 252, 253, 254 };
#declare LR = 519.4576369976315;  // line rate, Hz
#declare TAU = 0.00016209356048193865;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.126876 * sin(628.3185307 * T + 0.941505));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 596 x 4 samples spanning y/z in [-0.0422647998, 0.1368194736] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 39.33524181, 832.0105233>
  right <0, 149, 0>
  up <1, 0, 0>
  aperture 52.905941 blur_samples 19 focal_point <0, 57.60324466, 1218.4114> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 7909.0006
  pigment { function { max(0.002, min(0.98, 0.0173955 * (1 + 0.18565 * ((y / 7909.0006) - 0.04727733689) / 0.08954213669 + 0 * sin(21.256949 * ((y / 7909.0006) - 0.04727733689) / 0.08954213669 + 2.08945)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -0.2014471414, 1449.648061> + 43489.4 * <0.4990714069, -0.5498046937, -0.6698078303> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, -0.2014471414, 1449.648061>;  // mm
#declare V_0 = <-430.9288242, -220.9695599, -29.8804759>;  // mm/s
#declare TC_0 = 0.1925084797635884;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.7953635745, 0.7953635745, 0.778073062>] [0.44 rgb <0.7953635745, 0.7953635745, 0.778073062>] [0.46 rgb <0.6051679371, 0.7348467807, 0.1296788437>] [1.00 rgb <0.6051679371, 0.7348467807, 0.1296788437>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.4018 diffuse 0.5982 } }
  no_shadow
  rotate <249.3312013, 194.6583793, 67.52364893>
  transform { Axis_Rotate_Trans(<-0.3981315021, -0.4396911911, -0.805085687>, 200.7435 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
// ball 1: tennis
#declare C0_1 = <0, 154.4877497, 1494.639914>;  // mm
#declare V_1 = <-449.1756981, 19.26515716, 4.868448542>;  // mm/s
#declare TC_1 = 0.40936076429980217;  // s
#declare P_1 = C0_1 + V_1 * (T - TC_1);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.7953635745, 0.7953635745, 0.778073062>] [0.44 rgb <0.7953635745, 0.7953635745, 0.778073062>] [0.46 rgb <0.6051679371, 0.7348467807, 0.1296788437>] [1.00 rgb <0.6051679371, 0.7348467807, 0.1296788437>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.4018 diffuse 0.5982 } }
  no_shadow
  rotate <317.7931599, 163.6044725, 308.1814959>
  transform { Axis_Rotate_Trans(<-0.3981315021, -0.4396911911, -0.805085687>, 200.7435 * (T - TC_1)) }
  scale 33.5
  translate P_1 }
#end
