// validation scene pv1031_a000 (seed 1031)
#version 3.7;
#declare NS = 1;
#declare NLT = 47;
#declare LINES = array[47] { 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58 };
#declare LR = 10338.892441101896;  // line rate, Hz
#declare TAU = 3.866003514483654e-05;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.343597 * sin(628.3185307 * T + 1.69559));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 1200 x 4 samples spanning y/z in [-0.2549122309, -0.1998797799] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -309.9026134, 1362.832266>
  right <0, 75, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 13672.201
  pigment { function { max(0.002, min(0.98, 0.0561089 * (1 + 0.0302105 * ((y / 13672.201) - -0.2273960054) / 0.02751622553 + 0 * sin(4.5802403 * ((y / 13672.201) - -0.2273960054) / 0.02751622553 + 5.44287)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -671.95132, 3202.561431> + 96076.8 * <-0.5377179395, -0.5349068645, -0.6517162448> color rgb FL }
light_source { <0, -671.95132, 3202.561431> + 96076.8 * <-0.8356628998, -0.5228068236, 0.1683464972> color rgb FL * 0.5751 }


// ball 0: golf
#declare C0_0 = <0, -671.95132, 3202.561431>;  // mm
#declare V_0 = <10862.7444, 1412.701174, 640.0082614>;  // mm/s
#declare TC_0 = 0.0033852755698336465;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.654123991, 0.654123991, 0.654123991> }
  normal { leopard 0.5 scale 0.07 }
  finish { ambient 0.5068 diffuse 0.4932 phong 0.35 phong_size 40 } }
  no_shadow
  rotate <203.0759183, 147.0674339, 129.0259441>
  transform { Axis_Rotate_Trans(<-0.04766006512, 0.7919721958, -0.6086941426>, 2130.5713 * (T - TC_0)) }
  scale 21.35
  translate P_0 }
#end
