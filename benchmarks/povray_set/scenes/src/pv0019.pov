// validation scene pv0019 (seed 19)
#version 3.7;
#declare NS = 1;
#declare NLT = 51;
#declare LINES = array[51] { 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64 };
#declare LR = 121.42149635244778;  // line rate, Hz
#declare TAU = 0.005295540500353413;  // exposure, s
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
// film: 2544 x 4 samples spanning y/z in [-0.05312930226, 0.03677356705] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -14.46900858, 1769.288681>
  right <0, 159.0641291, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 30832.417
  pigment { function { max(0.002, min(0.98, 0.0834699 * (1 + 0.0656925 * ((y / 30832.417) - -0.008177867603) / 0.04495143466 + 0 * sin(14.529464 * ((y / 30832.417) - -0.008177867603) / 0.04495143466 + 3.47908)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -124.2432388, 6299.837072> + 188995 * <0.3015179517, 0.3410731422, -0.8903684835> color rgb FL }


// ball 0: pingpong
#declare C0_0 = <0, -124.2432388, 6299.837072>;  // mm
#declare V_0 = <112.0229994, -118.9181975, 10.70453266>;  // mm/s
#declare TC_0 = 0.3211951851325853;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.9007787539, 0.9007787539, 0.9007787539> }
  finish { ambient 0.2453 diffuse 0.7547 phong 0.362 phong_size 40 } }
  no_shadow
  rotate <200.432743, 144.514903, 226.3358939>
  transform { Axis_Rotate_Trans(<-0.9330101318, 0.3101308566, -0.1825128643>, 0 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
