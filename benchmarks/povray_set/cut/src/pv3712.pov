// validation scene pv3712 (seed 3712)
#version 3.7;
#declare NS = 1;
#declare NLT = 157;
#declare LINES = array[157] { 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214, 215, 216, 217, 218, 219, 220, 221, 222, 223, 224, 225, 226, 227, 228, 229, 230, 231, 232, 233, 234, 235, 236 };
#declare LR = 161205.9087970727;  // line rate, Hz
#declare TAU = 1.9560870417422393e-07;  // exposure, s
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
// film: 504 x 4 samples spanning y/z in [0.05271613105, 0.1327198505] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 146.0240464, 1574.926778>
  right <0, 126, 0>
  up <1, 0, 0>
  aperture 38.136086 blur_samples 19 focal_point <0, 508.1666433, 5480.7771> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 18326.839
  pigment { function { max(0.002, min(0.98, 0.0303998 * (1 + -0.115196 * ((y / 18326.839) - 0.09271799076) / 0.0400018597 + 0 * sin(22.132016 * ((y / 18326.839) - 0.09271799076) / 0.0400018597 + 4.23106)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 382.753563, 3891.712734> + 116751 * <0.3271820196, -0.533828821, -0.7797298993> color rgb FL }


// ball 0: pingpong
#declare C0_0 = <0, 382.753563, 3891.712734>;  // mm
#declare V_0 = <-25375.14814, -8591.478575, 6715.753114>;  // mm/s
#declare TC_0 = 0.0013399012580357866;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.7856411185, 0.3535385033, 0.03928205592> }
  finish { ambient 0.4414 diffuse 0.5586 phong 0.5516 phong_size 40 } }
  no_shadow
  rotate <303.2824615, 334.1458855, 353.2867508>
  transform { Axis_Rotate_Trans(<0.5286542691, 0.7806619693, 0.3333039954>, 3055.9818 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
