// validation scene pu2028 (seed 2028)
#version 3.7;
#declare NS = 1;
#declare NLT = 205;
#declare LINES = array[205] { 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214, 215, 216, 217, 218, 219, 220, 221, 222, 223, 224, 225, 226, 227, 228, 229, 230, 231, 232, 233, 234, 235, 236, 237, 238, 239, 240, 241, 242, 243, 244, 245, 246, 247, 248, 249, 250, 251, 252, 253, 254, 255, 256, 257, 258, 259, 260, 261, 262, 263 };
#declare LR = 1768.4929340709377;  // line rate, Hz
#declare TAU = 2.7971783596857493e-05;  // exposure, s
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
// film: 2384 x 4 samples spanning y/z in [-0.06736368629, 0.07087380935] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 1.891821714, 1077.9233>
  right <0, 149.0094175, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 20906.734
  pigment { function { max(0.002, min(0.98, 0.551452 * (1 + 0.0783445 * ((y / 20906.734) - 0.001755061528) / 0.06911874782 + 0 * sin(9.7306776 * ((y / 20906.734) - 0.001755061528) / 0.06911874782 + 6.1552)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 333.1742929, 8125.258311> + 243758 * <0.7597192099, -0.6374342965, -0.1284688278> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, 333.1742929, 8125.258311>;  // mm
#declare V_0 = <-2011.090613, -769.2696329, 863.8725636>;  // mm/s
#declare TC_0 = 0.09103796622437733;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.109345604, 0.109345604, 0.109345604> }
  finish { ambient 1 diffuse 0 } }
  no_shadow
  rotate <155.4373559, 188.9148135, 285.370885>
  transform { Axis_Rotate_Trans(<0.08100366665, 0.02247137597, 0.9964604574>, 1628.8253 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
