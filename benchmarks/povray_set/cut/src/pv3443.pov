// validation scene pv3443 (seed 3443)
#version 3.7;
#declare NS = 1;
#declare NLT = 75;
#declare LINES = array[75] { 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116 };
#declare LR = 3950.734499505654;  // line rate, Hz
#declare TAU = 0.00017808550966005523;  // exposure, s
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
// film: 3024 x 4 samples spanning y/z in [0.1241967964, 0.1938642643] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 431.4319312, 2712.887458>
  right <0, 189, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 40185.071
  pigment { function { max(0.002, min(0.98, 0.0197666 * (1 + -0.181147 * ((y / 40185.071) - 0.1590305304) / 0.03483373397 + 0.229877 * sin(10.209539 * ((y / 40185.071) - 0.1590305304) / 0.03483373397 + 2.60089)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 1234.874284, 7228.597294> + 216858 * <0.4147306237, -0.3605496404, -0.8354654191> color rgb FL }


// ball 0: golf
#declare C0_0 = <0, 1234.874284, 7228.597294>;  // mm
#declare V_0 = <-1249.92415, 448.5000567, -610.519506>;  // mm/s
#declare TC_0 = 0.029361628834971017;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.6625283064, 0.6625283064, 0.6625283064> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.469 diffuse 0.531 phong 0.3571 phong_size 40 } }
  no_shadow
  rotate <64.28013189, 146.0155589, 233.0112465>
  transform { Axis_Rotate_Trans(<0.3094234576, -0.8713242003, 0.3808559595>, 0 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
