// validation scene pu2036 (seed 2036)
#version 3.7;
#declare NS = 1;
#declare NLT = 103;
#declare LINES = array[103] { 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131 };
#declare LR = 353.4471743935342;  // line rate, Hz
#declare TAU = 0.001416145332145902;  // exposure, s
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
// film: 464 x 4 samples spanning y/z in [-0.0786105779, 0.06333064048] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -6.243685805, 817.239709>
  right <0, 116, 0>
  up <1, 0, 0>
  aperture 46.759731 blur_samples 19 focal_point <0, -18.45104634, 2415.0683> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 18319.296
  pigment { function { max(0.002, min(0.98, 0.0372996 * (1 + 0.393255 * ((y / 18319.296) - -0.00763996871) / 0.07097060919 + 0.00163762 * sin(22.496963 * ((y / 18319.296) - -0.00763996871) / 0.07097060919 + 3.57536)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -10.47895907, 3132.336313> + 93970.1 * <0.1338067675, 0.4527984945, -0.8815153273> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, -10.47895907, 3132.336313>;  // mm
#declare V_0 = <-166.4843444, -31.53411521, 5.50216227>;  // mm/s
#declare TC_0 = 0.22634216877605198;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.8249143675, 0.8249143675, 0.8249143675> }
  finish { ambient 1 diffuse 0 } }
  no_shadow
  rotate <359.4760922, 288.2772217, 60.51125799>
  transform { Axis_Rotate_Trans(<-0.4186817375, -0.5253759591, -0.7407332207>, 0 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
