// validation scene pv0272 (seed 272)
#version 3.7;
#declare NS = 1;
#declare NLT = 131;
#declare LINES = array[131] { 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175 };
#declare LR = 43155.935340062315;  // line rate, Hz
#declare TAU = 9.93248800642073e-06;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.20749 * sin(753.9822369 * T + 1.13316));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 1824 x 4 samples spanning y/z in [-0.05426693181, 0.07455321939] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 8.976222905, 884.9547135>
  right <0, 114, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 4234.1206
  pigment { function { max(0.002, min(0.98, 0.0112744 * (1 + -0.397633 * ((y / 4234.1206) - 0.01014314379) / 0.0644100756 + 0 * sin(12.10787 * ((y / 4234.1206) - 0.01014314379) / 0.0644100756 + 3.02801)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 5.341004912, 784.3670052> + 23531 * <-0.5756690504, 0.009423898793, -0.817628482> color rgb FL }
light_source { <0, 5.341004912, 784.3670052> + 23531 * <-0.8239028243, 0.2717511187, 0.4973283277> color rgb FL * 0.3963 }


// ball 0: plain
#declare C0_0 = <0, 5.341004912, 784.3670052>;  // mm
#declare V_0 = <11353.57956, 126.8075627, -137.2513213>;  // mm/s
#declare TC_0 = 0.002826957614025933;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.2108475363, 0.6429920261, 0.6263693608> }
  finish { ambient 0.2493 diffuse 0.7507 phong 0.5114 phong_size 40 } }
  no_shadow
  rotate <128.463087, 147.6585668, 71.31337305>
  transform { Axis_Rotate_Trans(<-0.5864812239, -0.7303939377, 0.3500920875>, 5945.6235 * (T - TC_0)) }
  scale 19.41901753
  translate P_0 }
#end
