// validation scene pv4100 (seed 4100)
#version 3.7;
#declare NS = 1;
#declare NLT = 93;
#declare LINES = array[93] { 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118 };
#declare LR = 3219.68516104208;  // line rate, Hz
#declare TAU = 1.6772313165596507e-05;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.327922 * sin(628.3185307 * T + 5.70793));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 484 x 4 samples spanning y/z in [-0.3816615047, -0.3579620883] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -2015.272636, 5449.454709>
  right <0, 129.1488964, 0>
  up <1, 0, 0>
  aperture 25.057477 blur_samples 19 focal_point <0, -2678.789763, 7243.6569> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 42871.847
  pigment { function { max(0.002, min(0.98, 0.292668 * (1 + -0.344779 * ((y / 42871.847) - -0.3698117965) / 0.01184970821 + 0.0762185 * sin(14.130594 * ((y / 42871.847) - -0.3698117965) / 0.01184970821 + 4.92648)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -3830.322371, 10576.4231> + 317293 * <0.5895987739, 0.6797644765, -0.4362264804> color rgb FL }
light_source { <0, -3830.322371, 10576.4231> + 317293 * <-0.5939332822, -0.8033291848, 0.04365177233> color rgb FL * 0.3553 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, -3830.322371, 10576.4231>;  // mm
#declare V_0 = <2691.971191, 3840.489136, -856.3840496>;  // mm/s
#declare TC_0 = 0.02236243495829777;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.7019288594, 0.6863304403, 0.639535183>] [0.5 rgb <0.7019288594, 0.6863304403, 0.639535183>] [0.5 rgb <0.5849407162, 0.06239367639, 0.04679525729>] [1.0 rgb <0.5849407162, 0.06239367639, 0.04679525729>] } }
  finish { ambient 0.1585 diffuse 0.8415 phong 0.1 phong_size 40 } }
  no_shadow
  rotate <109.3026653, 152.5861507, 310.607161>
  transform { Axis_Rotate_Trans(<0.09588634729, -0.8764405984, -0.4718661738>, 4060.3916 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
