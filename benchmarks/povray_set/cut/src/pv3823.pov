// validation scene pv3823 (seed 3823)
#version 3.7;
#declare NS = 1;
#declare NLT = 110;
#declare LINES = array[110] { 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183 };
#declare LR = 711.5775617493193;  // line rate, Hz
#declare TAU = 0.00020422192720520713;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.0960235 * sin(628.3185307 * T + 1.82971));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 2160 x 4 samples spanning y/z in [-0.07621450707, 0.05425311373] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -11.35533624, 1034.118014>
  right <0, 134.9189169, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 16090.8
  pigment { function { max(0.002, min(0.98, 0.799679 * (1 + 0.0737445 * ((y / 16090.8) - -0.01098069667) / 0.0652338104 + 0.0241691 * sin(14.607307 * ((y / 16090.8) - -0.01098069667) / 0.0652338104 + 1.87664)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 201.9955878, 7496.156627> + 224885 * <0.3545220378, 0.1370191215, -0.9249539908> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, 201.9955878, 7496.156627>;  // mm
#declare V_0 = <652.9495558, -28.88112934, 42.11846151>;  // mm/s
#declare TC_0 = 0.2796603078809636;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.2187772957, 0.2187772957, 0.2187772957>] [0.925 rgb <0.2187772957, 0.2187772957, 0.2187772957>] [0.935 rgb <0.01189007042, 0.01189007042, 0.01189007042>] [1.0 rgb <0.01189007042, 0.01189007042, 0.01189007042>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.2832 diffuse 0.7168 phong 0.3417 phong_size 40 } }
  no_shadow
  rotate <189.5557908, 350.1673821, 111.8383238>
  transform { Axis_Rotate_Trans(<0.7877960974, 0.474522151, 0.3926907653>, 382.80633 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
