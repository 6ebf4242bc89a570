// validation scene pv4018 (seed 4018)
#version 3.7;
#declare NS = 2;
#declare NLT = 167;
#declare LINES = array[167] { 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214 };
#declare LR = 12333.514942288242;  // line rate, Hz
#declare TAU = 6.905626642758237e-05;  // exposure, s
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
// film: 2608 x 4 samples spanning y/z in [-0.02087299629, 0.03056467501] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 15.35590155, 3168.883736>
  right <0, 163, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 12774.302
  pigment { function { max(0.002, min(0.98, 0.017821 * (1 + 0.0778057 * ((y / 12774.302) - 0.004845839364) / 0.02571883565 + 0.172948 * sin(23.91115 * ((y / 12774.302) - 0.004845839364) / 0.02571883565 + 5.94194)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -57.98626112, 3908.177122> + 117245 * <0.01328735405, 0.4884690049, -0.8724800728> color rgb FL }
light_source { <0, -57.98626112, 3908.177122> + 117245 * <-0.1885580727, 0.6789905284, -0.7095193553> color rgb FL * 0.526 }


// ball 0: pingpong
#declare C0_0 = <0, -57.98626112, 3908.177122>;  // mm
#declare V_0 = <3137.005777, 4975.07998, 69.67382261>;  // mm/s
#declare TC_0 = 0.010621465220010956;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.8542402901, 0.8542402901, 0.8542402901> }
  finish { ambient 0.5353 diffuse 0.4647 phong 0.3 phong_size 40 } }
  no_shadow
  rotate <35.72926503, 240.9772303, 37.36240028>
  transform { Axis_Rotate_Trans(<-0.8908849848, -0.4510816242, 0.05337894801>, 0 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
