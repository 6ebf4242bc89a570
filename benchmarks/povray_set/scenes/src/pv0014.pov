// validation scene pv0014 (seed 14)
#version 3.7;
#declare NS = 1;
#declare NLT = 135;
#declare LINES = array[135] { 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172 };
#declare LR = 2466.181952589323;  // line rate, Hz
#declare TAU = 8.193910439019004e-05;  // exposure, s
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
// film: 2512 x 4 samples spanning y/z in [-0.07540954915, 0.1024706335] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 11.94228098, 882.6165886>
  right <0, 157, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 14803.146
  pigment { function { max(0.002, min(0.98, 0.0204362 * (1 + -0.0905793 * ((y / 14803.146) - 0.01353054218) / 0.08894009133 + 0 * sin(10.772757 * ((y / 14803.146) - 0.01353054218) / 0.08894009133 + 3.60237)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 42.32656086, 3322.268988> + 99668.1 * <0.6773701023, -0.4837474307, -0.5542185199> color rgb FL }


// ball 0: pingpong
#declare C0_0 = <0, 42.32656086, 3322.268988>;  // mm
#declare V_0 = <-830.1273147, 839.1199849, -646.3337831>;  // mm/s
#declare TC_0 = 0.042575933981577135;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.8943498083, 0.4024574137, 0.04471749042> }
  finish { ambient 0.4472 diffuse 0.5528 phong 0.3 phong_size 40 } }
  no_shadow
  rotate <318.1526296, 300.4699661, 188.3622769>
  transform { Axis_Rotate_Trans(<-0.6756099773, -0.5677137573, 0.4703745831>, 1208.0657 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
