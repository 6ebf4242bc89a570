// validation scene pv3076 (seed 3076)
#version 3.7;
#declare NS = 1;
#declare NLT = 181;
#declare LINES = array[181] { 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214, 215, 216, 217, 218, 219, 220, 221, 222, 223, 224, 225, 226, 227, 228, 229, 230, 231, 232 };
#declare LR = 3521.115674655865;  // line rate, Hz
#declare TAU = 1.876290758319344e-05;  // exposure, s
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
// film: 352 x 4 samples spanning y/z in [0.2390712169, 0.3364219547] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 264.6311092, 919.6672427>
  right <0, 89.53028462, 0>
  up <1, 0, 0>
  aperture 17.360482 blur_samples 19 focal_point <0, 884.9609913, 3075.4874> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 11714.619
  pigment { function { max(0.002, min(0.98, 0.185065 * (1 + 0.028217 * ((y / 11714.619) - 0.2877465858) / 0.0486753689 + 0.162749 * sin(16.178982 * ((y / 11714.619) - 0.2877465858) / 0.0486753689 + 1.17355)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 1163.17689, 4585.371892> + 137561 * <0.3377844795, -0.6313514968, -0.6980665676> color rgb FL }
light_source { <0, 1163.17689, 4585.371892> + 137561 * <0.3044207802, 0.5148472848, -0.8014114186> color rgb FL * 0.2931 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, 1163.17689, 4585.371892>;  // mm
#declare V_0 = <4489.676808, 2687.192137, 1565.994908>;  // mm/s
#declare TC_0 = 0.04032812696898358;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.6948088501, 0.6948088501, 0.6948088501>] [0.925 rgb <0.6948088501, 0.6948088501, 0.6948088501>] [0.935 rgb <0.03776135055, 0.03776135055, 0.03776135055>] [1.0 rgb <0.03776135055, 0.03776135055, 0.03776135055>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.2541 diffuse 0.7459 } }
  no_shadow
  rotate <213.0626113, 251.5197617, 57.60107466>
  transform { Axis_Rotate_Trans(<-0.4394561415, -0.6241960445, -0.6459547954>, 4287.6848 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
