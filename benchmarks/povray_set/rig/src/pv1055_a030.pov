// validation scene pv1055_a030 (seed 1055)
#version 3.7;
#declare NS = 1;
#declare NLT = 169;
#declare LINES = array[169] { 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214, 215, 216 };
#declare LR = 51.229448243950905;  // line rate, Hz
#declare TAU = 0.015716739578914923;  // exposure, s
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
// film: 264 x 4 samples spanning y/z in [-0.02377140777, 0.02736242542] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 2.317518075, 1290.730538>
  right <0, 66, 0>
  up <1, 0, 0>
  aperture 152.47598 blur_samples 19 focal_point <0, 14.53584033, 8095.6663> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 13139.529
  pigment { function { max(0.002, min(0.98, 0.175723 * (1 + -0.399802 * ((y / 13139.529) - 0.001795508828) / 0.02556691659 + 0 * sin(3.8687078 * ((y / 13139.529) - 0.001795508828) / 0.02556691659 + 1.85856)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 6.413196231, 6134.324268> + 184030 * <0.3795443036, 0.9251286719, 0.009113838616> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, 6.413196231, 6134.324268>;  // mm
#declare V_0 = <-70.20666868, 2.72035758, -3.807368289>;  // mm/s
#declare TC_0 = 2.5766430153888367;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.6559569276, 0.6559569276, 0.6559569276>] [0.925 rgb <0.6559569276, 0.6559569276, 0.6559569276>] [0.935 rgb <0.03564983302, 0.03564983302, 0.03564983302>] [1.0 rgb <0.03564983302, 0.03564983302, 0.03564983302>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.135 diffuse 0.865 } }
  no_shadow
  rotate <21.93424146, 220.0491902, 86.60488891>
  transform { Axis_Rotate_Trans(<-0.2745960483, -0.6641131359, -0.6953781367>, 12.956764 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
