// validation scene pv4213 (seed 4213)
#version 3.7;
#declare NS = 1;
#declare NLT = 119;
#declare LINES = array[119] { 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151 };
#declare LR = 46.310412973266494;  // line rate, Hz
#declare TAU = 0.014963450836042924;  // exposure, s
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
// film: 2832 x 4 samples spanning y/z in [-0.1102211342, 0.0003504627966] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -87.9389887, 1600.772756>
  right <0, 177, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 33214.763
  pigment { function { max(0.002, min(0.98, 0.0118593 * (1 + 0.0606795 * ((y / 33214.763) - -0.05493533568) / 0.05528579848 + 0.0151093 * sin(10.171594 * ((y / 33214.763) - -0.05493533568) / 0.05528579848 + 2.89518)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -31.30788056, 6386.848852> + 191605 * <-0.196702102, 0.07502621313, -0.9775885384> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, -31.30788056, 6386.848852>;  // mm
#declare V_0 = <61.61837665, -5.596343863, 9.977172825>;  // mm/s
#declare TC_0 = 1.9865942472400027;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.87318905, 0.2328536053, 0.2603701439> }
  finish { ambient 0.1636 diffuse 0.8364 } }
  no_shadow
  rotate <254.9005186, 352.9999514, 332.9712164>
  transform { Axis_Rotate_Trans(<-0.985203213, -0.1249128095, 0.1173516896>, 0 * (T - TC_0)) }
  scale 73.83988671
  translate P_0 }
#end
