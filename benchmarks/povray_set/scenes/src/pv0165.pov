// validation scene pv0165 (seed 165)
#version 3.7;
#declare NS = 1;
#declare NLT = 39;
#declare LINES = array[39] { 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47 };
#declare LR = 51.84963739888785;  // line rate, Hz
#declare TAU = 0.002667370267396558;  // exposure, s
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
// film: 408 x 4 samples spanning y/z in [-0.01110845442, 0.007981515874] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -8.353784015, 5343.107261>
  right <0, 101.9997589, 0>
  up <1, 0, 0>
  aperture 11.535399 blur_samples 19 focal_point <0, -22.49485411, 14387.781> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 41088.387
  pigment { function { max(0.002, min(0.98, 0.017143 * (1 + -0.190569 * ((y / 41088.387) - -0.001563469271) / 0.009544985145 + 0.08048 * sin(9.3874121 * ((y / 41088.387) - -0.001563469271) / 0.009544985145 + 1.35816)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -35.90620627, 9526.580072> + 285797 * <-0.4198901562, -0.4080286212, -0.8106817508> color rgb FL }


// ball 0: golf
#declare C0_0 = <0, -35.90620627, 9526.580072>;  // mm
#declare V_0 = <67.0568988, -105.3279754, -28.69127423>;  // mm/s
#declare TC_0 = 0.5400230629308236;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.8992624438, 0.8992624438, 0.8992624438> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.2601 diffuse 0.7399 phong 0.35 phong_size 40 } }
  no_shadow
  rotate <51.58790584, 175.730833, 168.3111783>
  transform { Axis_Rotate_Trans(<-0.8955689803, 0.3422331846, 0.2843108315>, 40.897679 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
