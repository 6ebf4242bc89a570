// validation scene pv0073 (seed 73)
#version 3.7;
#declare NS = 1;
#declare NLT = 209;
#declare LINES = array[209] { 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214, 215, 216, 217, 218, 219, 220, 221, 222, 223, 224, 225, 226, 227, 228, 229, 230, 231, 232, 233, 234, 235, 236, 237, 238, 239, 240, 241, 242, 243, 244, 245, 246, 247, 248, 249, 250, 251, 252, 253, 254, 255, 256, 257, 258, 259, 260, 261, 262, 263, 264, 265, 266, 267, 268 };
#declare LR = 1019.9873575511352;  // line rate, Hz
#declare TAU = 0.00035988870929445807;  // exposure, s
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
// film: 1856 x 4 samples spanning y/z in [-0.01144055869, 0.01173709879] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 0.7420648783, 5004.81984>
  right <0, 116, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 75165.533
  pigment { function { max(0.002, min(0.98, 0.214523 * (1 + 0.171268 * ((y / 75165.533) - 0.0001482700481) / 0.01158882874 + 0.213896 * sin(10.266784 * ((y / 75165.533) - 0.0001482700481) / 0.01158882874 + 2.10246)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 23.31182632, 14682.48262> + 440474 * <0.6444340607, -0.3313472082, -0.6891398762> color rgb FL }
light_source { <0, 23.31182632, 14682.48262> + 440474 * <0.2412720763, 0.8520174117, 0.4646010281> color rgb FL * 0.6119 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, 23.31182632, 14682.48262>;  // mm
#declare V_0 = <-1114.508852, 184.4564472, -303.7681839>;  // mm/s
#declare TC_0 = 0.1607863066006464;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.8662812477, 0.8662812477, 0.8662812477>] [0.925 rgb <0.8662812477, 0.8662812477, 0.8662812477>] [0.935 rgb <0.04708050259, 0.04708050259, 0.04708050259>] [1.0 rgb <0.04708050259, 0.04708050259, 0.04708050259>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.117 diffuse 0.883 phong 0.2092 phong_size 40 } }
  no_shadow
  rotate <160.3445012, 61.97361893, 21.41016236>
  transform { Axis_Rotate_Trans(<0.5024599153, 0.8561394205, -0.1206620332>, 0 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
