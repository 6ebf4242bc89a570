// validation scene pv0226 (seed 226)
#version 3.7;
#declare NS = 1;
#declare NLT = 43;
#declare LINES = array[43] { 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52 };
#declare LR = 125.42364802946533;  // line rate, Hz
#declare TAU = 0.00034377586379909204;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.330103 * sin(753.9822369 * T + 2.05372));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 1360 x 4 samples spanning y/z in [0.01982907165, 0.06108555908] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 83.35348014, 2060.282038>
  right <0, 85, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 2824.8993
  pigment { function { max(0.002, min(0.98, 0.158084 * (1 + -0.141008 * ((y / 2824.8993) - 0.04045731536) / 0.02062824371 + 0 * sin(20.186792 * ((y / 2824.8993) - 0.04045731536) / 0.02062824371 + 4.55954)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 57.74754852, 1377.350694> + 41320.5 * <-0.9327882928, 0.2904995875, 0.2133447692> color rgb FL }
light_source { <0, 57.74754852, 1377.350694> + 41320.5 * <-0.469789093, -0.2965234494, -0.8314878544> color rgb FL * 0.3231 }


// ball 0: pingpong
#declare C0_0 = <0, 57.74754852, 1377.350694>;  // mm
#declare V_0 = <-133.4246859, 3.775345716, 74.95282059>;  // mm/s
#declare TC_0 = 0.24716232135679295;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.8093518831, 0.8093518831, 0.8093518831> }
  finish { ambient 0.1967 diffuse 0.8033 phong 0.3 phong_size 40 } }
  no_shadow
  rotate <323.9090887, 251.2564528, 33.38097624>
  transform { Axis_Rotate_Trans(<0.6590336845, 0.5560462982, -0.5064455715>, 82.338626 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
