// validation scene pu2025 (seed 2025)
#version 3.7;
#declare NS = 2;
#declare NLT = 55;
#declare LINES = array[55] { 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69 };
#declare LR = 265.27141204193964;  // line rate, Hz
#declare TAU = 0.000979214838259068;  // exposure, s
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
// film: 416 x 4 samples spanning y/z in [-0.03324024546, 0.02485268151] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -7.507855912, 1790.235153>
  right <0, 104, 0>
  up <1, 0, 0>
  aperture 11.610816 blur_samples 19 focal_point <0, -5.79311153, 1381.3573> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 2134.1254
  pigment { function { max(0.002, min(0.98, 0.0353468 * (1 + 0.136428 * ((y / 2134.1254) - -0.004193781973) / 0.02904646349 + 0 * sin(19.358994 * ((y / 2134.1254) - -0.004193781973) / 0.02904646349 + 0.379043)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -7.183313026, 909.5950547> + 27287.9 * <-0.208837087, -0.7588614287, -0.6168601163> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, -7.183313026, 909.5950547>;  // mm
#declare V_0 = <206.6930302, 0.495446373, 72.93924424>;  // mm/s
#declare TC_0 = 0.15832840665604692;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.6850511393, 0.3310067126, 0.5922299033> }
  finish { ambient 1 diffuse 0 } }
  no_shadow
  rotate <145.1412118, 246.4805543, 41.5027457>
  transform { Axis_Rotate_Trans(<-0.9612508805, -0.2691667448, 0.05954836907>, 111.84959 * (T - TC_0)) }
  scale 19.88009389
  translate P_0 }
#end
