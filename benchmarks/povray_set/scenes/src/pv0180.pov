// validation scene pv0180 (seed 180)
#version 3.7;
#declare NS = 1;
#declare NLT = 113;
#declare LINES = array[113] { 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144 };
#declare LR = 26388.433628461942;  // line rate, Hz
#declare TAU = 2.56885245817295e-05;  // exposure, s
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
// film: 2640 x 4 samples spanning y/z in [-0.03673545917, 0.04302352687] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 6.504164745, 2068.732417>
  right <0, 165, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 49143.696
  pigment { function { max(0.002, min(0.98, 0.0222447 * (1 + 0.0940273 * ((y / 49143.696) - 0.003144033849) / 0.03987949302 + 0.0801696 * sin(23.3809 * ((y / 49143.696) - 0.003144033849) / 0.03987949302 + 6.22273)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 150.28233, 8836.970711> + 265109 * <0.4580784776, -0.1437778853, -0.8772069471> color rgb FL }


// ball 0: pingpong
#declare C0_0 = <0, 150.28233, 8836.970711>;  // mm
#declare V_0 = <-10795.88751, -475.1698758, -331.3301663>;  // mm/s
#declare TC_0 = 0.003334794373891343;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.7171165164, 0.3227024324, 0.03585582582> }
  finish { ambient 0.2357 diffuse 0.7643 phong 0.4482 phong_size 40 } }
  no_shadow
  rotate <10.44411922, 212.7902317, 72.73667651>
  transform { Axis_Rotate_Trans(<-0.08852932227, 0.1423466353, -0.9858498844>, 6232.2962 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
