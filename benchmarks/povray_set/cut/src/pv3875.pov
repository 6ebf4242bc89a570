// validation scene pv3875 (seed 3875)
#version 3.7;
#declare NS = 1;
#declare NLT = 172;
#declare LINES = array[172] { 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214, 215, 216, 217, 218, 219, 220, 221, 222, 223, 224, 225, 226, 227, 228, 229, 230, 231, 232, 233, 234, 235, 236, 237, 238, 239, 240, 241, 242, 243, 244, 245, 246, 247, 248, 249, 250, 251 };
#declare LR = 1389.784034849185;  // line rate, Hz
#declare TAU = 0.00011751734705317665;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.30948 * sin(753.9822369 * T + 4.70559));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 1696 x 4 samples spanning y/z in [-0.02472740183, 0.02590083895] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 1.22828678, 2093.48548>
  right <0, 105.989487, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 8772.2636
  pigment { function { max(0.002, min(0.98, 0.106307 * (1 + -0.249942 * ((y / 8772.2636) - 0.0005867185569) / 0.02531412039 + 0.240547 * sin(17.702357 * ((y / 8772.2636) - 0.0005867185569) / 0.02531412039 + 2.51919)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -1.11011983, 1503.375809> + 45101.3 * <0.3762714124, -0.4664988373, -0.8004990062> color rgb FL }
light_source { <0, -1.11011983, 1503.375809> + 45101.3 * <-0.06667039381, -0.7874463114, 0.6127669746> color rgb FL * 0.6683 }


// ball 0: golf
#declare C0_0 = <0, -1.11011983, 1503.375809>;  // mm
#declare V_0 = <224.0742041, -19.50571512, -21.25474383>;  // mm/s
#declare TC_0 = 0.15541983112753172;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.8731510676, 0.8731510676, 0.8731510676> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.309 diffuse 0.691 phong 0.35 phong_size 40 } }
  no_shadow
  rotate <152.7085246, 36.97351298, 327.3100095>
  transform { Axis_Rotate_Trans(<0.03827177985, 0.1997083138, -0.9791076857>, 0 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
