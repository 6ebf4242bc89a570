// validation scene pv0175 (seed 175)
#version 3.7;
#declare NS = 2;
#declare NLT = 175;
#declare LINES = array[175] { 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214, 215, 216, 217, 218, 219, 220, 221, 222, 223, 224, 225, 226, 227, 228, 229, 230, 231, 232, 233, 234, 235, 236, 237, 238 };
#declare LR = 2504.0745648065886;  // line rate, Hz
#declare TAU = 0.0002246196130904626;  // exposure, s
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
// film: 2512 x 4 samples spanning y/z in [-0.04889944663, 0.04883081231] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -0.0551292334, 1606.46254>
  right <0, 157, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 3357.925
  pigment { function { max(0.002, min(0.98, 0.0391298 * (1 + -0.0879458 * ((y / 3357.925) - -3.431716086e-05) / 0.04886512947 + 0 * sin(15.066713 * ((y / 3357.925) - -3.431716086e-05) / 0.04886512947 + 6.00675)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -50.73189541, 1633.477318> + 49004.3 * <0.5460576617, 0.484262604, -0.6836013169> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, -50.73189541, 1633.477318>;  // mm
#declare V_0 = <1506.298978, 2.677169984, 700.8281537>;  // mm/s
#declare TC_0 = 0.03913621478263343;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.2039054084, 0.6520354384, 0.3034605112> }
  finish { ambient 0.3251 diffuse 0.6749 } }
  no_shadow
  rotate <34.06108725, 47.99628685, 221.8434212>
  transform { Axis_Rotate_Trans(<-0.7665767194, -0.3825832255, -0.5157423862>, 1231.0746 * (T - TC_0)) }
  scale 25.20529475
  translate P_0 }
#end
// ball 1: plain
#declare C0_1 = <0, 48.83797447, 1654.618102>;  // mm
#declare V_1 = <1629.239474, 46.51255592, -164.6950635>;  // mm/s
#declare TC_1 = 0.07849665053548716;  // s
#declare P_1 = C0_1 + V_1 * (T - TC_1);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.2039054084, 0.6520354384, 0.3034605112> }
  finish { ambient 0.3251 diffuse 0.6749 } }
  no_shadow
  rotate <289.3816243, 313.4967356, 72.37663706>
  transform { Axis_Rotate_Trans(<-0.7665767194, -0.3825832255, -0.5157423862>, 1231.0746 * (T - TC_1)) }
  scale 25.20529475
  translate P_1 }
#end
