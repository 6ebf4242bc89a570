// validation scene pv0223 (seed 223)
#version 3.7;
#declare NS = 1;
#declare NLT = 119;
#declare LINES = array[119] { 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152 };
#declare LR = 1169.9160445157108;  // line rate, Hz
#declare TAU = 0.00012578575328602698;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.33411 * sin(753.9822369 * T + 0.598648));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 1312 x 4 samples spanning y/z in [-0.03991752103, 0.05081135571] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 4.919846182, 903.2349632>
  right <0, 81.94949365, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 9281.8301
  pigment { function { max(0.002, min(0.98, 0.606712 * (1 + -0.293992 * ((y / 9281.8301) - 0.005446917339) / 0.04536443837 + 0.163255 * sin(3.3833536 * ((y / 9281.8301) - 0.005446917339) / 0.04536443837 + 5.91431)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 74.47780976, 3010.003093> + 90300.1 * <0.6443334841, 0.09835358292, -0.7583936537> color rgb FL }


// ball 0: pingpong
#declare C0_0 = <0, 74.47780976, 3010.003093>;  // mm
#declare V_0 = <-440.0525097, -192.0399322, 2.961577538>;  // mm/s
#declare TC_0 = 0.0794928836440546;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.2827833096, 0.1272524893, 0.01413916548> }
  finish { ambient 0.4326 diffuse 0.5674 phong 0.3 phong_size 40 } }
  no_shadow
  rotate <211.9683338, 217.3296338, 139.8996859>
  transform { Axis_Rotate_Trans(<-0.6590746295, 0.0509798057, -0.7503477142>, 411.19978 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
