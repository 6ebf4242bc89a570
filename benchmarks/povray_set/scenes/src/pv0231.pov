// validation scene pv0231 (seed 231)
#version 3.7;
#declare NS = 1;
#declare NLT = 139;
#declare LINES = array[139] { 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178 };
#declare LR = 2148.3697844059284;  // line rate, Hz
#declare TAU = 0.0001528016644073609;  // exposure, s
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
// film: 628 x 4 samples spanning y/z in [-0.1284160776, 0.0008597646] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -77.45585254, 1214.457375>
  right <0, 157, 0>
  up <1, 0, 0>
  aperture 2.3334337 blur_samples 19 focal_point <0, -38.07904163, 597.0546> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 4677.1579
  pigment { function { max(0.002, min(0.98, 0.101175 * (1 + 0.330823 * ((y / 4677.1579) - -0.06377815651) / 0.06463792111 + 0 * sin(18.801467 * ((y / 4677.1579) - -0.06377815651) / 0.06463792111 + 1.87053)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -33.87121746, 904.3147736> + 27129.4 * <-0.1784593922, -0.05570841942, -0.9823689823> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, -33.87121746, 904.3147736>;  // mm
#declare V_0 = <-369.8455182, 96.39434883, -22.97394725>;  // mm/s
#declare TC_0 = 0.050736144583294306;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.5663151134, 0.6211200236, 0.2658001722> }
  finish { ambient 0.1804 diffuse 0.8196 phong 0.5374 phong_size 40 } }
  no_shadow
  rotate <0.6131795524, 22.92952392, 48.27411475>
  transform { Axis_Rotate_Trans(<0.9604576477, -0.1692247062, 0.2210975028>, 176.97919 * (T - TC_0)) }
  scale 11.23597679
  translate P_0 }
#end
