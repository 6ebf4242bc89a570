// validation scene pv0105 (seed 105)
#version 3.7;
#declare NS = 1;
#declare NLT = 159;
#declare LINES = array[159] { 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204 };
#declare LR = 9705.175260008475;  // line rate, Hz
#declare TAU = 4.313037114663102e-05;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.222148 * sin(628.3185307 * T + 2.62352));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 740 x 4 samples spanning y/z in [-0.06240826663, 0.06611174768] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 2.665514776, 1439.464514>
  right <0, 185, 0>
  up <1, 0, 0>
  aperture 12.349147 blur_samples 19 focal_point <0, 2.962055579, 1599.6062> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 7868.7712
  pigment { function { max(0.002, min(0.98, 0.0163672 * (1 + -0.230874 * ((y / 7868.7712) - 0.001851740526) / 0.06426000716 + 0 * sin(9.8912902 * ((y / 7868.7712) - 0.001851740526) / 0.06426000716 + 4.88088)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 46.616778, 2019.729941> + 60591.9 * <0.3937243331, -0.1845269573, -0.9005170468> color rgb FL }


// ball 0: golf
#declare C0_0 = <0, 46.616778, 2019.729941>;  // mm
#declare V_0 = <2764.319036, -1285.605341, 1061.748088>;  // mm/s
#declare TC_0 = 0.012879726192589215;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.8048497409, 0.8048497409, 0.8048497409> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.235 diffuse 0.765 phong 0.3601 phong_size 40 } }
  no_shadow
  rotate <247.2536682, 230.4262015, 231.6508138>
  transform { Axis_Rotate_Trans(<-0.7413373603, 0.6039593088, 0.2926637515>, 0 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
