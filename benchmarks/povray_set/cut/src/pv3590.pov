// validation scene pv3590 (seed 3590)
#version 3.7;
#declare NS = 1;
#declare NLT = 64;
#declare LINES = array[64] { 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95 };
#declare LR = 5118.539502814047;  // line rate, Hz
#declare TAU = 5.5139945249957105e-05;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.298224 * sin(628.3185307 * T + 1.13247));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 600 x 4 samples spanning y/z in [-0.04493142317, 0.07655955223] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 19.52536794, 1234.683715>
  right <0, 150.0029288, 0>
  up <1, 0, 0>
  aperture 50.112905 blur_samples 19 focal_point <0, 53.63486807, 3391.5928> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 14702.411
  pigment { function { max(0.002, min(0.98, 0.0116056 * (1 + 0.033708 * ((y / 14702.411) - 0.01581406453) / 0.0607454877 + 0.0747793 * sin(19.188275 * ((y / 14702.411) - 0.01581406453) / 0.0607454877 + 3.19378)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 146.6266682, 4685.095689> + 140553 * <-0.07095519177, 0.4823236505, -0.8731146871> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, 146.6266682, 4685.095689>;  // mm
#declare V_0 = <-10347.74424, 11783.58178, 296.9842855>;  // mm/s
#declare TC_0 = 0.017387772420447273;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.6588382573, 0.6588382573, 0.6588382573>] [0.925 rgb <0.6588382573, 0.6588382573, 0.6588382573>] [0.935 rgb <0.03580642703, 0.03580642703, 0.03580642703>] [1.0 rgb <0.03580642703, 0.03580642703, 0.03580642703>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.329 diffuse 0.671 phong 0.3416 phong_size 40 } }
  no_shadow
  rotate <195.835373, 59.34207142, 111.1369845>
  transform { Axis_Rotate_Trans(<0.5528975276, -0.09238947331, 0.8281114111>, 9027.7374 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
