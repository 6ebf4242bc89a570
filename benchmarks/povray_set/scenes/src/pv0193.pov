// validation scene pv0193 (seed 193)
#version 3.7;
#declare NS = 1;
#declare NLT = 70;
#declare LINES = array[70] { 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92 };
#declare LR = 4340.248881384001;  // line rate, Hz
#declare TAU = 1.8352847060762888e-05;  // exposure, s
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
// film: 288 x 4 samples spanning y/z in [0.2063206088, 0.222533155] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 960.8757814, 4481.134888>
  right <0, 72.65060665, 0>
  up <1, 0, 0>
  aperture 27.380858 blur_samples 19 focal_point <0, 1125.492921, 5248.8425> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 26152.577
  pigment { function { max(0.002, min(0.98, 0.170288 * (1 + 0.367851 * ((y / 26152.577) - 0.2144268819) / 0.008106273128 + 0 * sin(16.347385 * ((y / 26152.577) - 0.2144268819) / 0.008106273128 + 0.583261)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 1650.199883, 7854.406973> + 235632 * <-0.08241570003, 0.6367628371, -0.7666425123> color rgb FL }


// ball 0: pingpong
#declare C0_0 = <0, 1650.199883, 7854.406973>;  // mm
#declare V_0 = <6514.269926, -1016.670553, -163.2489208>;  // mm/s
#declare TC_0 = 0.008064053688285116;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.7242364924, 0.7242364924, 0.7242364924> }
  finish { ambient 0.2167 diffuse 0.7833 phong 0.3 phong_size 40 } }
  no_shadow
  rotate <155.2671577, 98.18034429, 350.3721669>
  transform { Axis_Rotate_Trans(<0.5491298448, 0.1290854481, 0.8257077937>, 3125.3662 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
// ball 1: pingpong
#declare C0_1 = <0, 1730.230854, 7925.15385>;  // mm
#declare V_1 = <5206.466431, 177.5701297, -430.4644713>;  // mm/s
#declare TC_1 = 0.016791221842155868;  // s
#declare P_1 = C0_1 + V_1 * (T - TC_1);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.7242364924, 0.7242364924, 0.7242364924> }
  finish { ambient 0.2167 diffuse 0.7833 phong 0.3 phong_size 40 } }
  no_shadow
  rotate <254.1376521, 148.9636278, 128.1123999>
  transform { Axis_Rotate_Trans(<0.5491298448, 0.1290854481, 0.8257077937>, 3125.3662 * (T - TC_1)) }
  scale 20
  translate P_1 }
#end
