// validation scene pv0000 (seed 0)
#version 3.7;
#declare NS = 2;
#declare NLT = 33;
#declare LINES = array[33] { 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40 };
#declare LR = 2586.314916634765;  // line rate, Hz
#declare TAU = 0.00013833992990202983;  // exposure, s
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
// film: 748 x 4 samples spanning y/z in [0.04381028285, 0.07198656774] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 384.2595138, 6636.786956>
  right <0, 187, 0>
  up <1, 0, 0>
  aperture 18.438355 blur_samples 19 focal_point <0, 638.1129143, 11021.248> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 49026.956
  pigment { function { max(0.002, min(0.98, 0.229208 * (1 + -0.311079 * ((y / 49026.956) - 0.0578984253) / 0.01408814244 + 0 * sin(4.2194133 * ((y / 49026.956) - 0.0578984253) / 0.01408814244 + 3.51535)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 411.7878886, 8278.680883> + 248360 * <-0.6089472622, -0.6396609567, -0.4690597961> color rgb FL }


// ball 0: pingpong
#declare C0_0 = <0, 411.7878886, 8278.680883>;  // mm
#declare V_0 = <3708.768744, 2124.024486, 315.6832107>;  // mm/s
#declare TC_0 = 0.009279612411325407;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.9813340512, 0.441600323, 0.04906670256> }
  finish { ambient 0.5119 diffuse 0.4881 phong 0.3 phong_size 40 } }
  no_shadow
  rotate <251.8309625, 22.91692735, 119.7659924>
  transform { Axis_Rotate_Trans(<-0.07210114501, -0.9232854959, -0.3772867848>, 2711.7578 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
