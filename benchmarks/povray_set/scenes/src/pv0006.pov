// validation scene pv0006 (seed 6)
#version 3.7;
#declare NS = 1;
#declare NLT = 143;
#declare LINES = array[143] { 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182 };
#declare LR = 142.3147244221708;  // line rate, Hz
#declare TAU = 0.0034007348624387167;  // exposure, s
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
// film: 1872 x 4 samples spanning y/z in [-0.3405523278, -0.2613122027] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -444.3339155, 1476.524676>
  right <0, 117, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 30234.208
  pigment { function { max(0.002, min(0.98, 0.035014 * (1 + -0.319746 * ((y / 30234.208) - -0.3009322653) / 0.03962006253 + 0.0113646 * sin(18.264177 * ((y / 30234.208) - -0.3009322653) / 0.03962006253 + 5.79858)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -2648.80636, 7966.90738> + 239007 * <-0.02655491818, -0.1534332879, -0.9878021373> color rgb FL }


// ball 0: golf
#declare C0_0 = <0, -2648.80636, 7966.90738>;  // mm
#declare V_0 = <49.71886362, 7.014463735, -3.347245765>;  // mm/s
#declare TC_0 = 0.7799614583149038;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.855063418, 0.855063418, 0.855063418> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.1951 diffuse 0.8049 phong 0.35 phong_size 40 } }
  no_shadow
  rotate <264.69593, 353.2419814, 156.8816073>
  transform { Axis_Rotate_Trans(<-0.662991173, 0.5361053669, -0.5225263056>, 41.903076 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
