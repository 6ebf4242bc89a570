// validation scene pv3619 (seed 3619)
#version 3.7;
#declare NS = 3;
#declare NLT = 99;
#declare LINES = array[99] { 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126 };
#declare LR = 350.1224107938959;  // line rate, Hz
#declare TAU = 0.00268150499446511;  // exposure, s
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
// film: 520 x 4 samples spanning y/z in [-0.01436769312, 0.01281380455] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -3.715864305, 4782.66509>
  right <0, 130, 0>
  up <1, 0, 0>
  aperture 4.6474154 blur_samples 19 focal_point <0, -1.236370523, 1591.3246> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 10763.293
  pigment { function { max(0.002, min(0.98, 0.0631849 * (1 + -0.0837305 * ((y / 10763.293) - -0.0007769442842) / 0.01359074884 + 0.140551 * sin(8.5776976 * ((y / 10763.293) - -0.0007769442842) / 0.01359074884 + 5.02936)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -23.09330225, 2225.33209> + 66760 * <-0.3764416168, 0.2963834116, -0.8777520051> color rgb FL }
light_source { <0, -23.09330225, 2225.33209> + 66760 * <0.5379492978, 0.7326349889, -0.4169610606> color rgb FL * 0.3387 }


// ball 0: plain
#declare C0_0 = <0, -23.09330225, 2225.33209>;  // mm
#declare V_0 = <-123.5090865, -17.73891663, 35.10167993>;  // mm/s
#declare TC_0 = 0.21992308297376328;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.5271187525, 0.5960225519, 0.6286347216> }
  finish { ambient 0.5022 diffuse 0.4978 } }
  no_shadow
  rotate <346.2219017, 286.2093872, 352.2824654>
  transform { Axis_Rotate_Trans(<-0.2933794855, -0.4554714794, -0.8405202014>, 115.20579 * (T - TC_0)) }
  scale 16.44897116
  translate P_0 }
#end
