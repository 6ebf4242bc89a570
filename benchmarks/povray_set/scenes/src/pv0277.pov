// validation scene pv0277 (seed 277)
#version 3.7;
#declare NS = 1;
#declare NLT = 41;
#declare LINES = array[41] { 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50 };
#declare LR = 57.234054458449705;  // line rate, Hz
#declare TAU = 0.004217181100916018;  // exposure, s
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
// film: 3168 x 4 samples spanning y/z in [-0.3740288401, -0.2389797428] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -449.3761966, 1466.133458>
  right <0, 198, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 51186.767
  pigment { function { max(0.002, min(0.98, 0.0109759 * (1 + -0.328156 * ((y / 51186.767) - -0.3065042914) / 0.06752454865 + 0 * sin(15.996235 * ((y / 51186.767) - -0.3065042914) / 0.06752454865 + 2.16796)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -2991.340356, 8566.133176> + 256984 * <0.1962063537, 0.3943241679, -0.8977814419> color rgb FL }


// ball 0: pingpong
#declare C0_0 = <0, -2991.340356, 8566.133176>;  // mm
#declare V_0 = <-70.52826173, -6.11005226, 1.903759967>;  // mm/s
#declare TC_0 = 0.5241634597419469;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.7964990758, 0.7964990758, 0.7964990758> }
  finish { ambient 0.3654 diffuse 0.6346 phong 0.3 phong_size 40 } }
  no_shadow
  rotate <24.43775491, 115.3207359, 214.0278431>
  transform { Axis_Rotate_Trans(<0.7013856058, 0.5495388435, 0.4539441502>, 32.574135 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
