// validation scene pv0288 (seed 288)
#version 3.7;
#declare NS = 1;
#declare NLT = 51;
#declare LINES = array[51] { 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64 };
#declare LR = 831.5922917115098;  // line rate, Hz
#declare TAU = 0.00012534744125477623;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.12951 * sin(628.3185307 * T + 5.39005));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 2128 x 4 samples spanning y/z in [-0.3422059671, -0.3215790174] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -2089.605047, 6296.029878>
  right <0, 129.8678913, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 60655.62
  pigment { function { max(0.002, min(0.98, 0.470881 * (1 + -0.126361 * ((y / 60655.62) - -0.3318924922) / 0.01031347483 + 0.127199 * sin(8.7508799 * ((y / 60655.62) - -0.3318924922) / 0.01031347483 + 4.52627)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -3795.436083, 11241.6333> + 337249 * <0.4078632311, -0.8348578652, -0.3696754381> color rgb FL }


// ball 0: golf
#declare C0_0 = <0, -3795.436083, 11241.6333>;  // mm
#declare V_0 = <774.8756466, -50.40607575, -375.4622041>;  // mm/s
#declare TC_0 = 0.04689798160554572;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.2113511741, 0.2113511741, 0.2113511741> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.2942 diffuse 0.7058 phong 0.35 phong_size 40 } }
  no_shadow
  rotate <277.0278022, 37.83647846, 317.1422948>
  transform { Axis_Rotate_Trans(<0.6350412679, 0.2537131548, 0.7296247139>, 193.66962 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
