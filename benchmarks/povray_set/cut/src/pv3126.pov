// validation scene pv3126 (seed 3126)
#version 3.7;
#declare NS = 1;
#declare NLT = 127;
#declare LINES = array[127] { 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162 };
#declare LR = 11198.945346850473;  // line rate, Hz
#declare TAU = 8.249337213985613e-05;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.0904641 * sin(628.3185307 * T + 3.83222));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 1296 x 4 samples spanning y/z in [0.08314079595, 0.1138646949] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 259.6910763, 2636.384146>
  right <0, 81, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 27554.545
  pigment { function { max(0.002, min(0.98, 0.774989 * (1 + -0.208324 * ((y / 27554.545) - 0.09850274541) / 0.01536194946 + 0.0903027 * sin(9.5595861 * ((y / 27554.545) - 0.09850274541) / 0.01536194946 + 0.403673)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 549.4687252, 4814.021132> + 144421 * <-0.2026560063, 0.1631011672, -0.9655716195> color rgb FL }
light_source { <0, 549.4687252, 4814.021132> + 144421 * <-0.7064104228, 0.6940753583, 0.1387217054> color rgb FL * 0.373 }


// ball 0: golf
#declare C0_0 = <0, 549.4687252, 4814.021132>;  // mm
#declare V_0 = <-4091.307678, 115.6623631, 309.2363645>;  // mm/s
#declare TC_0 = 0.00884011814807563;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.2116742887, 0.2116742887, 0.2116742887> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.2604 diffuse 0.7396 phong 0.355 phong_size 40 } }
  no_shadow
  rotate <333.6560686, 91.61969188, 52.06096207>
  transform { Axis_Rotate_Trans(<0.6041083108, 0.538916673, -0.5870451161>, 0 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
