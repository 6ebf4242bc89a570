// validation scene pv0218 (seed 218)
#version 3.7;
#declare NS = 4;
#declare NLT = 75;
#declare LINES = array[75] { 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94 };
#declare LR = 13243.85900281506;  // line rate, Hz
#declare TAU = 5.5190967451450106e-05;  // exposure, s
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
// film: 736 x 4 samples spanning y/z in [0.0295937588, 0.2369495355] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 118.3280023, 887.8707876>
  right <0, 184.1051368, 0>
  up <1, 0, 0>
  aperture 7.8255217 blur_samples 19 focal_point <0, 109.6164834, 822.50415> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 5015.8374
  pigment { function { max(0.002, min(0.98, 0.184268 * (1 + 0.384623 * ((y / 5015.8374) - 0.1332716472) / 0.1036778884 + 0.155373 * sin(20.933592 * ((y / 5015.8374) - 0.1332716472) / 0.1036778884 + 1.47293)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 113.9189078, 1177.677875> + 35330.3 * <-0.05301163844, 0.1967623053, -0.9790170384> color rgb FL }
light_source { <0, 113.9189078, 1177.677875> + 35330.3 * <-0.9135921143, 0.4029511234, -0.05458791936> color rgb FL * 0.5435 }


// ball 0: golf
#declare C0_0 = <0, 113.9189078, 1177.677875>;  // mm
#declare V_0 = <-20735.30455, 2020.701152, 1151.358231>;  // mm/s
#declare TC_0 = 0.0027182409592512264;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.6699063485, 0.6699063485, 0.6699063485> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.3421 diffuse 0.6579 phong 0.521 phong_size 40 } }
  no_shadow
  rotate <163.9185357, 31.18096426, 119.9037356>
  transform { Axis_Rotate_Trans(<-0.05157585914, -0.5746030548, 0.8168055216>, 11113.688 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
// ball 1: golf
#declare C0_1 = <0, 239.5039569, 1157.156882>;  // mm
#declare V_1 = <-15784.42233, 2414.273915, -159.5079658>;  // mm/s
#declare TC_1 = 0.00554760855201552;  // s
#declare P_1 = C0_1 + V_1 * (T - TC_1);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.6699063485, 0.6699063485, 0.6699063485> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.3421 diffuse 0.6579 phong 0.521 phong_size 40 } }
  no_shadow
  rotate <265.5264208, 324.232867, 295.30732>
  transform { Axis_Rotate_Trans(<-0.05157585914, -0.5746030548, 0.8168055216>, 11113.688 * (T - TC_1)) }
  scale 21.35
  translate P_1 }
#end
