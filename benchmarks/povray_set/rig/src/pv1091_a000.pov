// validation scene pv1091_a000 (seed 1091)
#version 3.7;
#declare NS = 1;
#declare NLT = 139;
#declare LINES = array[139] { 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178 };
#declare LR = 15509.752409623998;  // line rate, Hz
#declare TAU = 1.9684832862112483e-06;  // exposure, s
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
// film: 1792 x 4 samples spanning y/z in [-0.04023299242, 0.08725579973] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 20.64969549, 878.2842487>
  right <0, 111.971398, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 4203.6938
  pigment { function { max(0.002, min(0.98, 0.0652094 * (1 + -0.324295 * ((y / 4203.6938) - 0.02351140365) / 0.06374439608 + 0.00699669 * sin(24.741004 * ((y / 4203.6938) - 0.02351140365) / 0.06374439608 + 1.2091)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 28.75198507, 860.1659156> + 25805 * <0.4195125494, 0.4815033427, -0.7695217682> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, 28.75198507, 860.1659156>;  // mm
#declare V_0 = <-8510.424686, -2305.198633, -1816.909619>;  // mm/s
#declare TC_0 = 0.0070278362362744175;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.8954150878, 0.8755169748, 0.8158226356>] [0.5 rgb <0.8954150878, 0.8755169748, 0.8158226356>] [0.5 rgb <0.7461792398, 0.07959245225, 0.05969433919>] [1.0 rgb <0.7461792398, 0.07959245225, 0.05969433919>] } }
  finish { ambient 0.5059 diffuse 0.4941 phong 0.1 phong_size 40 } }
  no_shadow
  rotate <75.96879542, 148.9230422, 34.66140324>
  transform { Axis_Rotate_Trans(<-0.9407645089, 0.03946225127, 0.3367563948>, 0 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
