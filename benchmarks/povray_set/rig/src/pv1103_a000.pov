// validation scene pv1103_a000 (seed 1103)
#version 3.7;
#declare NS = 1;
#declare NLT = 49;
#declare LINES = array[49] { 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61 };
#declare LR = 59.39898509757941;  // line rate, Hz
#declare TAU = 0.0005140040701743085;  // exposure, s
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
// film: 664 x 4 samples spanning y/z in [-0.05430795895, 0.05953003034] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 3.80744537, 1458.212685>
  right <0, 166, 0>
  up <1, 0, 0>
  aperture 7.9226999 blur_samples 19 focal_point <0, 5.104516101, 1954.9775> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 3314.1651
  pigment { function { max(0.002, min(0.98, 0.0264161 * (1 + 0.180866 * ((y / 3314.1651) - 0.002611035694) / 0.05691899464 + 0 * sin(16.266615 * ((y / 3314.1651) - 0.002611035694) / 0.05691899464 + 2.65018)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 1.531041293, 1275.127356> + 38253.8 * <-0.217056287, -0.5600481348, -0.7995202656> color rgb FL }
light_source { <0, 1.531041293, 1275.127356> + 38253.8 * <-0.01913797156, -0.9088258488, 0.4167365049> color rgb FL * 0.5098 }


// ball 0: pingpong
#declare C0_0 = <0, 1.531041293, 1275.127356>;  // mm
#declare V_0 = <52.93287069, -1.216108572, -26.95790741>;  // mm/s
#declare TC_0 = 0.6229062658093766;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.909222821, 0.4091502694, 0.04546114105> }
  finish { ambient 0.5201 diffuse 0.4799 phong 0.3655 phong_size 40 } }
  no_shadow
  rotate <148.4143796, 333.5908394, 348.6229437>
  transform { Axis_Rotate_Trans(<0.3469823099, 0.9378294515, 0.008899242179>, 0 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
