// validation scene pv1097_a090 (seed 1097)
#version 3.7;
#declare NS = 1;
#declare NLT = 85;
#declare LINES = array[85] { 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107 };
#declare LR = 297.9454468036866;  // line rate, Hz
#declare TAU = 0.0014877045817127392;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.32188 * sin(753.9822369 * T + 2.05614));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 2848 x 4 samples spanning y/z in [-0.07274385164, 0.08672830264] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 7.792752078, 1114.488095>
  right <0, 177.7298175, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 26822.497
  pigment { function { max(0.002, min(0.98, 0.0126985 * (1 + 0.157457 * ((y / 26822.497) - 0.006992225499) / 0.07973607714 + 0.111292 * sin(4.4632467 * ((y / 26822.497) - 0.006992225499) / 0.07973607714 + 0.699879)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 656.7577597, 9423.054745> + 282692 * <-0.385260669, 0.9032041848, -0.189199412> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, 656.7577597, 9423.054745>;  // mm
#declare V_0 = <-669.3902671, -486.8855802, -749.5619995>;  // mm/s
#declare TC_0 = 0.2181607428383622;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.7096168806, 0.6145775091, 0.6909772339> }
  finish { ambient 0.3026 diffuse 0.6974 } }
  no_shadow
  rotate <93.8452044, 294.5640394, 269.2224696>
  transform { Axis_Rotate_Trans(<-0.07817563125, 0.2042656491, -0.9757889707>, 154.12502 * (T - TC_0)) }
  scale 86.06240916
  translate P_0 }
#end
