// validation scene pv0147 (seed 147)
#version 3.7;
#declare NS = 1;
#declare NLT = 77;
#declare LINES = array[77] { 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96 };
#declare LR = 148.7221146154062;  // line rate, Hz
#declare TAU = 0.00024046299623276167;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.133115 * sin(628.3185307 * T + 2.04828));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 400 x 4 samples spanning y/z in [-0.0399618559, 0.05217840912] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 6.629323898, 1085.301849>
  right <0, 100, 0>
  up <1, 0, 0>
  aperture 9.1677964 blur_samples 19 focal_point <0, 3.467744277, 567.71238> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 1770.7339
  pigment { function { max(0.002, min(0.98, 0.551885 * (1 + 0.360687 * ((y / 1770.7339) - 0.006108276609) / 0.04607013251 + 0.210435 * sin(18.206612 * ((y / 1770.7339) - 0.006108276609) / 0.04607013251 + 3.19448)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 1.662042416, 731.987083> + 21959.6 * <-0.1793406866, 0.9837776591, 0.004293665132> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, 1.662042416, 731.987083>;  // mm
#declare V_0 = <80.12213332, -1.37072009, -23.80177037>;  // mm/s
#declare TC_0 = 0.3899890755990619;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.1011040723, 0.08068534931, 0.2690673883> }
  finish { ambient 0.4435 diffuse 0.5565 } }
  no_shadow
  rotate <225.8054796, 69.06784477, 79.79949435>
  transform { Axis_Rotate_Trans(<0.916747245, -0.1482935112, -0.37092253>, 9.0907873 * (T - TC_0)) }
  scale 19.06665874
  translate P_0 }
#end
