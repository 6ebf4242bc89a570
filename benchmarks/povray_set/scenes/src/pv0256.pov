// validation scene pv0256 (seed 256)
#version 3.7;
#declare NS = 1;
#declare NLT = 83;
#declare LINES = array[83] { 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105 };
#declare LR = 1244.0970237770482;  // line rate, Hz
#declare TAU = 0.0003208048827640752;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.295067 * sin(753.9822369 * T + 3.03467));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 552 x 4 samples spanning y/z in [-0.02809872463, 0.03045371156] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 2.775189363, 2356.861798>
  right <0, 138, 0>
  up <1, 0, 0>
  aperture 90.697637 blur_samples 19 focal_point <0, 18.29181734, 15534.538> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 45302.243
  pigment { function { max(0.002, min(0.98, 0.633579 * (1 + 0.198497 * ((y / 45302.243) - 0.001177493464) / 0.02927621809 + 0 * sin(4.2373309 * ((y / 45302.243) - 0.001177493464) / 0.02927621809 + 3.33827)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 263.9823328, 10523.76088> + 315713 * <-0.1894760646, -0.4810134541, -0.8559935034> color rgb FL }


// ball 0: golf
#declare C0_0 = <0, 263.9823328, 10523.76088>;  // mm
#declare V_0 = <-738.7873025, 51.89634222, -56.9189303>;  // mm/s
#declare TC_0 = 0.05144293312887894;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.156392257, 0.156392257, 0.156392257> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.3986 diffuse 0.6014 phong 0.767 phong_size 40 } }
  no_shadow
  rotate <106.3376073, 274.690974, 124.8515435>
  transform { Axis_Rotate_Trans(<0.6843185235, -0.06962982293, 0.7258511184>, 446.04112 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
