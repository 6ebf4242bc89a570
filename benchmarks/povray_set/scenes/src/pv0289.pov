// validation scene pv0289 (seed 289)
#version 3.7;
#declare NS = 1;
#declare NLT = 143;
#declare LINES = array[143] { 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182 };
#declare LR = 14431.155534343334;  // line rate, Hz
#declare TAU = 1.0280197632477122e-05;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.115867 * sin(628.3185307 * T + 5.27908));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 3040 x 4 samples spanning y/z in [-0.02000842405, 0.0227053426] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 5.998758069, 4448.601593>
  right <0, 190.0165303, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 34065.993
  pigment { function { max(0.002, min(0.98, 0.753009 * (1 + -0.1836 * ((y / 34065.993) - 0.001348459273) / 0.02135688332 + 0 * sin(24.170706 * ((y / 34065.993) - 0.001348459273) / 0.02135688332 + 5.8993)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 73.14796378, 6737.523958> + 202126 * <-0.4380973764, 0.5037041088, -0.7445487624> color rgb FL }
light_source { <0, 73.14796378, 6737.523958> + 202126 * <-0.9915545661, -0.03983209389, 0.1234218246> color rgb FL * 0.6119 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, 73.14796378, 6737.523958>;  // mm
#declare V_0 = <7810.02207, -12227.29981, 3144.735506>;  // mm/s
#declare TC_0 = 0.007691691752323067;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.2100522174, 0.2053843903, 0.1913809092>] [0.5 rgb <0.2100522174, 0.2053843903, 0.1913809092>] [0.5 rgb <0.1750435145, 0.01867130821, 0.01400348116>] [1.0 rgb <0.1750435145, 0.01867130821, 0.01400348116>] } }
  finish { ambient 0.4968 diffuse 0.5032 phong 0.2746 phong_size 40 } }
  no_shadow
  rotate <59.56810832, 3.035865464, 269.4248463>
  transform { Axis_Rotate_Trans(<0.3826251652, -0.9213174673, -0.06908044194>, 6119.752 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
