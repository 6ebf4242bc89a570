// validation scene pu2035 (seed 2035)
#version 3.7;
#declare NS = 1;
#declare NLT = 181;
#declare LINES = array[181] { 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214, 215, 216, 217, 218, 219, 220, 221, 222, 223, 224, 225, 226, 227, 228, 229, 230, 231 };
#declare LR = 19596.16276677753;  // line rate, Hz
#declare TAU = 1.8929238809987894e-06;  // exposure, s
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
// film: 2224 x 4 samples spanning y/z in [-0.04303932957, 0.07452648874] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 18.60297715, 1181.623089>
  right <0, 138.9184854, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 14279.842
  pigment { function { max(0.002, min(0.98, 0.746959 * (1 + 0.311186 * ((y / 14279.842) - 0.01574357959) / 0.05878290915 + 0.208098 * sin(15.564994 * ((y / 14279.842) - 0.01574357959) / 0.05878290915 + 5.24438)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -18.58876315, 4446.777667> + 133403 * <0.6441643998, 0.3101835952, -0.6991697672> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, -18.58876315, 4446.777667>;  // mm
#declare V_0 = <-24907.10703, -24301.08256, 15167.03516>;  // mm/s
#declare TC_0 = 0.007195286224048169;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.1019400979, 0.1019400979, 0.1019400979> }
  finish { ambient 1 diffuse 0 } }
  no_shadow
  rotate <118.3437229, 217.506549, 177.7066597>
  transform { Axis_Rotate_Trans(<0.1042549919, 0.4874968435, -0.8668781484>, 10501.891 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
