// validation scene pv0279 (seed 279)
#version 3.7;
#declare NS = 1;
#declare NLT = 109;
#declare LINES = array[109] { 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138 };
#declare LR = 11664.703124672527;  // line rate, Hz
#declare TAU = 4.399025308123135e-06;  // exposure, s
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
// film: 1520 x 4 samples spanning y/z in [-0.1350796482, -0.04313988945] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -92.07581308, 1033.285288>
  right <0, 95, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 22897.525
  pigment { function { max(0.002, min(0.98, 0.557586 * (1 + -0.139252 * ((y / 22897.525) - -0.0891097688) / 0.04596987935 + 0.0473132 * sin(19.08862 * ((y / 22897.525) - -0.0891097688) / 0.04596987935 + 3.30558)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -635.8597811, 6490.563864> + 194717 * <0.7069461101, 0.4196945597, -0.5692834741> color rgb FL }


// ball 0: golf
#declare C0_0 = <0, -635.8597811, 6490.563864>;  // mm
#declare V_0 = <5460.367057, -641.3158489, -357.5152775>;  // mm/s
#declare TC_0 = 0.007201211989898646;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.1600986219, 0.1600986219, 0.1600986219> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.49 diffuse 0.51 phong 0.35 phong_size 40 } }
  no_shadow
  rotate <174.9158213, 249.7171854, 269.1913634>
  transform { Axis_Rotate_Trans(<0.9124961398, 0.183175431, -0.365783483>, 2300.0508 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
