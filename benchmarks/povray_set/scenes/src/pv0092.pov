// validation scene pv0092 (seed 92)
#version 3.7;
#declare NS = 1;
#declare NLT = 199;
#declare LINES = array[199] { 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214, 215, 216, 217, 218, 219, 220, 221, 222, 223, 224, 225, 226, 227, 228, 229, 230, 231, 232, 233, 234, 235, 236, 237, 238, 239, 240, 241, 242, 243, 244, 245, 246, 247, 248, 249, 250, 251, 252, 253, 254, 255 };
#declare LR = 78464.86076739011;  // line rate, Hz
#declare TAU = 1.967899212415407e-06;  // exposure, s
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
// film: 468 x 4 samples spanning y/z in [-0.01097788883, 0.01985054641] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 16.83608585, 3795.04916>
  right <0, 116.9954273, 0>
  up <1, 0, 0>
  aperture 14.626286 blur_samples 19 focal_point <0, 22.71246285, 5119.6527> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 11262.166
  pigment { function { max(0.002, min(0.98, 0.0143181 * (1 + -0.242842 * ((y / 11262.166) - 0.004436328791) / 0.01541421762 + 0 * sin(9.9353508 * ((y / 11262.166) - 0.004436328791) / 0.01541421762 + 5.7361)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -30.52455208, 3934.695259> + 118041 * <-0.9397137553, 0.3417898776, -0.01085070158> color rgb FL }
light_source { <0, -30.52455208, 3934.695259> + 118041 * <0.8547343198, -0.4645999969, -0.2314650845> color rgb FL * 0.3551 }


// ball 0: plain
#declare C0_0 = <0, -30.52455208, 3934.695259>;  // mm
#declare V_0 = <18047.11767, 22330.00313, 1324.389504>;  // mm/s
#declare TC_0 = 0.00198815110960897;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.3134184898, 0.4969234343, 0.5288605946> }
  finish { ambient 0.5891 diffuse 0.4109 } }
  no_shadow
  rotate <12.53332939, 212.2847575, 207.4213261>
  transform { Axis_Rotate_Trans(<-0.823954396, -0.1444297722, -0.5479408675>, 8298.3927 * (T - TC_0)) }
  scale 21.83681604
  translate P_0 }
#end
