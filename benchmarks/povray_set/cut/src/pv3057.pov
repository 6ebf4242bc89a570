// validation scene pv3057 (seed 3057)
#version 3.7;
#declare NS = 2;
#declare NLT = 151;
#declare LINES = array[151] { 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192 };
#declare LR = 601.9878081394797;  // line rate, Hz
#declare TAU = 0.0016420490953215135;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.225036 * sin(753.9822369 * T + 1.16852));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 412 x 4 samples spanning y/z in [0.004685357883, 0.1098546309] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 56.0741676, 979.1194881>
  right <0, 102.9732848, 0>
  up <1, 0, 0>
  aperture 245.986 blur_samples 19 focal_point <0, 496.6199528, 8671.5558> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 53467.185
  pigment { function { max(0.002, min(0.98, 0.182573 * (1 + -0.0898596 * ((y / 53467.185) - 0.0572699944) / 0.05258463651 + 0 * sin(10.822342 * ((y / 53467.185) - 0.0572699944) / 0.05258463651 + 4.86929)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 1109.087601, 11648.91083> + 349467 * <-0.5161306411, -0.8098555115, 0.2788246971> color rgb FL }
light_source { <0, 1109.087601, 11648.91083> + 349467 * <-0.7457576038, -0.6648111347, 0.04326374356> color rgb FL * 0.2494 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, 1109.087601, 11648.91083>;  // mm
#declare V_0 = <962.1867068, 1620.445694, 49.22851888>;  // mm/s
#declare TC_0 = 0.19435609561861966;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.7254847471, 0.7254847471, 0.7254847471>] [0.925 rgb <0.7254847471, 0.7254847471, 0.7254847471>] [0.935 rgb <0.03942851886, 0.03942851886, 0.03942851886>] [1.0 rgb <0.03942851886, 0.03942851886, 0.03942851886>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.3506 diffuse 0.6494 phong 0.3375 phong_size 40 } }
  no_shadow
  rotate <103.601402, 79.01168854, 88.18409604>
  transform { Axis_Rotate_Trans(<-0.8805508916, -0.348706721, 0.3209887069>, 105.47235 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
