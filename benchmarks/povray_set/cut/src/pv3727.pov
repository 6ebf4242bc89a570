// validation scene pv3727 (seed 3727)
#version 3.7;
#declare NS = 2;
#declare NLT = 191;
#declare LINES = array[191] { 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214, 215, 216, 217, 218, 219, 220, 221, 222, 223, 224, 225, 226, 227, 228, 229, 230, 231, 232, 233, 234, 235, 236, 237, 238, 239, 240, 241, 242, 243, 244, 245 };
#declare LR = 228937.2336688631;  // line rate, Hz
#declare TAU = 3.783519589105986e-06;  // exposure, s
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
// film: 2176 x 4 samples spanning y/z in [-0.02311419309, 0.0420094382] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 19.7249836, 2087.825109>
  right <0, 135.9667526, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 2595.6702
  pigment { function { max(0.002, min(0.98, 0.462318 * (1 + 0.0521608 * ((y / 2595.6702) - 0.009447622558) / 0.03256181565 + 0 * sin(9.9630443 * ((y / 2595.6702) - 0.009447622558) / 0.03256181565 + 0.436933)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -22.36470183, 1159.558295> + 34786.7 * <0.6705767135, -0.322127875, -0.6682518263> color rgb FL }
light_source { <0, -22.36470183, 1159.558295> + 34786.7 * <0.7301586328, 0.3773374852, 0.5696356671> color rgb FL * 0.2142 }


// ball 0: pingpong
#declare C0_0 = <0, -22.36470183, 1159.558295>;  // mm
#declare V_0 = <49837.7764, 29901.19403, 16164.39319>;  // mm/s
#declare TC_0 = 0.0006552014174197691;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.2778408107, 0.2778408107, 0.2778408107> }
  finish { ambient 0.4447 diffuse 0.5553 phong 0.3 phong_size 40 } }
  no_shadow
  rotate <61.89885319, 336.2488207, 313.6855458>
  transform { Axis_Rotate_Trans(<0.2088986301, -0.3861374526, -0.8984760598>, 17176.421 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
