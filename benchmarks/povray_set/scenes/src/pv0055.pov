// validation scene pv0055 (seed 55)
#version 3.7;
#declare NS = 1;
#declare NLT = 47;
#declare LINES = array[47] { 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58 };
#declare LR = 13978.159998800238;  // line rate, Hz
#declare TAU = 6.574626352237338e-06;  // exposure, s
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
// film: 580 x 4 samples spanning y/z in [0.3015662437, 0.3212674053] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 2292.019144, 7359.972114>
  right <0, 145, 0>
  up <1, 0, 0>
  aperture 12.73218 blur_samples 19 focal_point <0, 5399.849462, 17339.62> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 48079.007
  pigment { function { max(0.002, min(0.98, 0.0432724 * (1 + -0.163088 * ((y / 48079.007) - 0.3114168245) / 0.0098505808 + 0.0162384 * sin(23.150308 * ((y / 48079.007) - 0.3114168245) / 0.0098505808 + 2.26602)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 4066.156299, 12978.73548> + 389362 * <-0.209338514, 0.5397246233, -0.8153985023> color rgb FL }


// ball 0: golf
#declare C0_0 = <0, 4066.156299, 12978.73548>;  // mm
#declare V_0 = <-14245.97086, 65.85152453, 4913.766928>;  // mm/s
#declare TC_0 = 0.002503906093720782;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.7524689961, 0.7524689961, 0.7524689961> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.2748 diffuse 0.7252 phong 0.35 phong_size 40 } }
  no_shadow
  rotate <143.3101603, 218.5072748, 222.8596764>
  transform { Axis_Rotate_Trans(<-0.08074601366, -0.2217534758, -0.9717538151>, 0 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
