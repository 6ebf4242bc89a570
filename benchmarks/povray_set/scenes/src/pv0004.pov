// validation scene pv0004 (seed 4)
#version 3.7;
#declare NS = 1;
#declare NLT = 73;
#declare LINES = array[73] { 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92 };
#declare LR = 494.6216903397655;  // line rate, Hz
#declare TAU = 0.0002372936190923508;  // exposure, s
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
// film: 1632 x 4 samples spanning y/z in [-0.01231575142, 0.01091900017] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -3.065877978, 4390.012885>
  right <0, 102.0008589, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 16519.198
  pigment { function { max(0.002, min(0.98, 0.732191 * (1 + 0.285077 * ((y / 16519.198) - -0.0006983756219) / 0.01161737579 + 0.0842027 * sin(8.7879241 * ((y / 16519.198) - -0.0006983756219) / 0.01161737579 + 3.18537)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 5.47317659, 4305.182309> + 129155 * <0.05475246973, 0.6040521943, -0.7950617043> color rgb FL }
light_source { <0, 5.47317659, 4305.182309> + 129155 * <0.5087305422, 0.3366388508, -0.7923809182> color rgb FL * 0.3611 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, 5.47317659, 4305.182309>;  // mm
#declare V_0 = <529.5289874, -90.63505776, 134.8405259>;  // mm/s
#declare TC_0 = 0.11321784121827023;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.09901685324, 0.09681647872, 0.09021535517>] [0.5 rgb <0.09901685324, 0.09681647872, 0.09021535517>] [0.5 rgb <0.08251404436, 0.008801498066, 0.006601123549>] [1.0 rgb <0.08251404436, 0.008801498066, 0.006601123549>] } }
  finish { ambient 0.2034 diffuse 0.7966 phong 0.49 phong_size 40 } }
  no_shadow
  rotate <248.9865697, 198.9799513, 170.7196901>
  transform { Axis_Rotate_Trans(<-0.2310937416, 0.8112955518, -0.5370244037>, 263.89878 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
