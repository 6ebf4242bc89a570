// validation scene pv0144 (seed 144)
#version 3.7;
#declare NS = 1;
#declare NLT = 121;
#declare LINES = array[121] { 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155 };
#declare LR = 2750.0115022977584;  // line rate, Hz
#declare TAU = 0.00012733761863104758;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.220221 * sin(628.3185307 * T + 1.71209));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 1984 x 4 samples spanning y/z in [-0.03722836189, 0.04280305978] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 4.319069971, 1549.52611>
  right <0, 124.0107775, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 17442.305
  pigment { function { max(0.002, min(0.98, 0.479709 * (1 + 0.187109 * ((y / 17442.305) - 0.002787348947) / 0.04001571083 + 0 * sin(14.35331 * ((y / 17442.305) - 0.002787348947) / 0.04001571083 + 0.214617)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -24.71784921, 3602.848836> + 108085 * <-0.7034975744, 0.3551777565, -0.6155809647> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, -24.71784921, 3602.848836>;  // mm
#declare V_0 = <3897.504599, -866.3740247, -1766.391335>;  // mm/s
#declare TC_0 = 0.03454531005438458;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.0826532541, 0.03871948177, 0.05125437134> }
  finish { ambient 0.4564 diffuse 0.5436 phong 0.2125 phong_size 40 } }
  no_shadow
  rotate <123.7661305, 336.3137043, 138.4032133>
  transform { Axis_Rotate_Trans(<-0.1910979851, 0.3162164553, -0.929240934>, 1854.731 * (T - TC_0)) }
  scale 82.12940403
  translate P_0 }
#end
