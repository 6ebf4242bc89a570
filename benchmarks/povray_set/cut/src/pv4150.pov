// validation scene pv4150 (seed 4150)
#version 3.7;
#declare NS = 1;
#declare NLT = 55;
#declare LINES = array[55] { 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79 };
#declare LR = 1783.5338684109227;  // line rate, Hz
#declare TAU = 2.384600585526409e-05;  // exposure, s
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
// film: 2944 x 4 samples spanning y/z in [-0.1023210698, 0.0931760629] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -4.29132168, 938.5059479>
  right <0, 183.4752218, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 2311.708
  pigment { function { max(0.002, min(0.98, 0.0106877 * (1 + 0.394972 * ((y / 2311.708) - -0.004572503445) / 0.09774856634 + 0.190203 * sin(19.183665 * ((y / 2311.708) - -0.004572503445) / 0.09774856634 + 2.51378)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 5.267703653, 472.6320083> + 14179 * <0.7782874013, -0.6038630895, 0.1720990705> color rgb FL }
light_source { <0, 5.267703653, 472.6320083> + 14179 * <-0.9129527964, 0.3846704554, -0.1361830841> color rgb FL * 0.6893 }


// ball 0: pingpong
#declare C0_0 = <0, 5.267703653, 472.6320083>;  // mm
#declare V_0 = <-831.3177291, 345.8400751, -12.04842005>;  // mm/s
#declare TC_0 = 0.03924792303628525;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.7585805935, 0.7585805935, 0.7585805935> }
  finish { ambient 0.2726 diffuse 0.7274 phong 0.3 phong_size 40 } }
  no_shadow
  rotate <161.780351, 337.771959, 177.4643555>
  transform { Axis_Rotate_Trans(<-0.8723984552, 0.488747279, 0.006858036668>, 2.6004829 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
