// validation scene pv3099 (seed 3099)
#version 3.7;
#declare NS = 1;
#declare NLT = 99;
#declare LINES = array[99] { 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126 };
#declare LR = 54735.034437209644;  // line rate, Hz
#declare TAU = 1.6544893650148649e-06;  // exposure, s
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
// film: 648 x 4 samples spanning y/z in [-0.02046997271, 0.0233282975] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 5.286151873, 3698.776212>
  right <0, 162, 0>
  up <1, 0, 0>
  aperture 16.949635 blur_samples 19 focal_point <0, 4.528309352, 3168.5058> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 15161.465
  pigment { function { max(0.002, min(0.98, 0.0102958 * (1 + 0.0953893 * ((y / 15161.465) - 0.001429162396) / 0.0218991351 + 0.162072 * sin(6.8047305 * ((y / 15161.465) - 0.001429162396) / 0.0218991351 + 5.22899)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -77.94622194, 4476.487324> + 134295 * <0.468447599, 0.1575591295, -0.8693284579> color rgb FL }
light_source { <0, -77.94622194, 4476.487324> + 134295 * <0.5401659767, -0.4683190409, -0.6992124095> color rgb FL * 0.4525 }


// ball 0: golf
#declare C0_0 = <0, -77.94622194, 4476.487324>;  // mm
#declare V_0 = <-25184.80934, -4010.504928, -820.6224872>;  // mm/s
#declare TC_0 = 0.0014067772276334647;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.8172483854, 0.8172483854, 0.8172483854> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.357 diffuse 0.643 phong 0.35 phong_size 40 } }
  no_shadow
  rotate <291.6849596, 340.1395255, 318.2094251>
  transform { Axis_Rotate_Trans(<0.5465239937, 0.7730000819, 0.3221527553>, 0 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
