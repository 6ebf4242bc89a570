// validation scene pv0142 (seed 142)
#version 3.7;
#declare NS = 1;
#declare NLT = 229;
#declare LINES = array[229] { 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 255, 256, 257, 258, 259, 260, 261, 262, 263, 264, 265, 266, 267, 268, 269, 270, 271, 272, 273, 274, 275, 276, 277, 278, 279, 280, 281, 282, 283, 284, 285, 286, 287, 288, 289, 290, 291, 292, 293, 294, 295, 296, 297, 298, 299, 300, 301, 302, 303, 304, 305, 306, 307, 308, 309, 310, 311, 312, 313, 314, 315, 316, 317, 318, 319, 320, 321, 322, 323, 324, 325, 326, 327, 328, 329, 330, 331, 332, 333, 334, 335, 336, 337, 338, 339, 340, 341, 342, 343, 344, 345, 346, 347, 348, 349, 350, 351, 352, 353, 354, 355, 356, 357, 358, 359, 360 };
#declare LR = 169861.6826872832;  // line rate, Hz
#declare TAU = 2.2955527358916604e-06;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.194552 * sin(628.3185307 * T + 5.91434));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 624 x 4 samples spanning y/z in [-0.009714750167, 0.008480192726] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -5.292431033, 8573.810916>
  right <0, 156, 0>
  up <1, 0, 0>
  aperture 5.0235919 blur_samples 19 focal_point <0, -2.495108737, 4042.1104> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 23634.5
  pigment { function { max(0.002, min(0.98, 0.117483 * (1 + 0.373986 * ((y / 23634.5) - -0.0006172787206) / 0.009097471447 + 0 * sin(7.575697 * ((y / 23634.5) - -0.0006172787206) / 0.009097471447 + 3.25405)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -30.94669543, 5564.076972> + 166922 * <-0.4329249285, 0.3637009431, -0.8248015703> color rgb FL }
light_source { <0, -30.94669543, 5564.076972> + 166922 * <-0.9962476903, -0.05327961567, -0.06820426779> color rgb FL * 0.3085 }


// ball 0: pingpong
#declare C0_0 = <0, -30.94669543, 5564.076972>;  // mm
#declare V_0 = <-58707.66361, 345.8473241, -3621.479749>;  // mm/s
#declare TC_0 = 0.0008359742924566643;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.7610351203, 0.7610351203, 0.7610351203> }
  finish { ambient 0.4281 diffuse 0.5719 phong 0.3 phong_size 40 } }
  no_shadow
  rotate <24.20033036, 210.7030163, 284.221327>
  transform { Axis_Rotate_Trans(<0.461145709, -0.2940643139, 0.8371802759>, 17039.117 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
// ball 1: pingpong
#declare C0_1 = <0, 22.90003584, 5367.336604>;  // mm
#declare V_1 = <-67748.31901, -709.961922, 2037.721106>;  // mm/s
#declare TC_1 = 0.0018098437302067395;  // s
#declare P_1 = C0_1 + V_1 * (T - TC_1);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.7610351203, 0.7610351203, 0.7610351203> }
  finish { ambient 0.4281 diffuse 0.5719 phong 0.3 phong_size 40 } }
  no_shadow
  rotate <155.5013171, 201.099491, 283.3684197>
  transform { Axis_Rotate_Trans(<0.461145709, -0.2940643139, 0.8371802759>, 17039.117 * (T - TC_1)) }
  scale 20
  translate P_1 }
#end
