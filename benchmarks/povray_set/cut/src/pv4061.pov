// validation scene pv4061 (seed 4061)
#version 3.7;
#declare NS = 1;
#declare NLT = 163;
#declare LINES = array[163] { 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208 };
#declare LR = 1091.7881947465476;  // line rate, Hz
#declare TAU = 0.0005307723095031073;  // exposure, s
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
// film: 3200 x 4 samples spanning y/z in [-0.01855193786, 0.0136112451] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -15.3624014, 6218.723629>
  right <0, 200.0139459, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 82182.714
  pigment { function { max(0.002, min(0.98, 0.0211964 * (1 + 0.365287 * ((y / 82182.714) - -0.002470346379) / 0.01608159148 + 0.0209935 * sin(5.119727 * ((y / 82182.714) - -0.002470346379) / 0.01608159148 + 2.70081)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -253.0965652, 14132.56518> + 423977 * <-0.636358611, 0.4604017256, -0.6189329279> color rgb FL }
light_source { <0, -253.0965652, 14132.56518> + 423977 * <-0.5083853467, -0.8116282701, 0.2877566514> color rgb FL * 0.2371 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, -253.0965652, 14132.56518>;  // mm
#declare V_0 = <-478.7376923, -55.2743849, -9.094513895>;  // mm/s
#declare TC_0 = 0.11632292839499178;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.710798476, 0.710798476, 0.6953463352>] [0.44 rgb <0.710798476, 0.710798476, 0.6953463352>] [0.46 rgb <0.5408249274, 0.6567159832, 0.1158910559>] [1.00 rgb <0.5408249274, 0.6567159832, 0.1158910559>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.2849 diffuse 0.7151 } }
  no_shadow
  rotate <30.04822679, 57.38623389, 200.1692811>
  transform { Axis_Rotate_Trans(<-0.1670535304, 0.9533226671, -0.2515333185>, 115.18104 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
