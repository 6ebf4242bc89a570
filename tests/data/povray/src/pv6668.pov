// validation scene pv6668 (seed 6668)
#version 3.7;
#declare NS = 1;
#declare NLT = 185;
#declare LINES = array[185] { 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214, 215, 216, 217, 218, 219, 220, 221, 222, 223, 224, 225, 226, 227, 228, 229, 230, 231, 232, 233, 234, 235, 236, 237, 238, 239, 240, 241, 242, 243, 244, 245, 246, 247, 248, 249, 250, 251, 252, 253, 254, 255, 256, 257 };
#declare LR = 11818.229170901946;  // line rate, Hz
#declare TAU = 1.1899868247150902e-05;  // exposure, s
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
// film: 1056 x 4 samples spanning y/z in [-0.007827256241, 0.008340862308] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 1.048297621, 4082.107624>
  right <0, 66, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 20157.363
  pigment { function { max(0.002, min(0.98, 0.0353593 * (1 + 0.163454 * ((y / 20157.363) - 0.0002568030334) / 0.008084059274 + 0.0903964 * sin(10.433277 * ((y / 20157.363) - 0.0002568030334) / 0.008084059274 + 1.36597)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 7.138015715, 5038.638696> + 151159 * <-0.2194967344, 0.2798176546, -0.9346246646> color rgb FL }


// ball 0: pingpong
#declare C0_0 = <0, 7.138015715, 5038.638696>;  // mm
#declare V_0 = <-1979.242381, -267.157976, 143.8658363>;  // mm/s
#declare TC_0 = 0.016753779025329985;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.7164993891, 0.3224247251, 0.03582496946> }
  finish { ambient 0.3724 diffuse 0.6276 phong 0.2786 phong_size 40 } }
  no_shadow
  rotate <56.82514617, 31.3417271, 56.06725585>
  transform { Axis_Rotate_Trans(<0.4198032922, -0.8981921164, -0.1304458431>, 3.6684623 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
