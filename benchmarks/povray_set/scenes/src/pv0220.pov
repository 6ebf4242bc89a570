// validation scene pv0220 (seed 220)
#version 3.7;
#declare NS = 2;
#declare NLT = 59;
#declare LINES = array[59] { 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73 };
#declare LR = 27.040946704128263;  // line rate, Hz
#declare TAU = 0.006341099388001277;  // exposure, s
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
// film: 2720 x 4 samples spanning y/z in [-0.2229211105, -0.1291238114] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -316.8656212, 1800.143115>
  right <0, 168.848562, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 11828.072
  pigment { function { max(0.002, min(0.98, 0.849061 * (1 + -0.272468 * ((y / 11828.072) - -0.176022461) / 0.04689864952 + 0 * sin(23.610592 * ((y / 11828.072) - -0.176022461) / 0.04689864952 + 0.203499)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -465.8799105, 2890.254293> + 86707.6 * <0.7139393226, -0.2759935027, -0.6435201862> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, -465.8799105, 2890.254293>;  // mm
#declare V_0 = <-37.06151067, 55.11100682, -3.399708702>;  // mm/s
#declare TC_0 = 1.6271619659411793;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.2559469661, 0.2502592557, 0.2331961246>] [0.5 rgb <0.2559469661, 0.2502592557, 0.2331961246>] [0.5 rgb <0.2132891384, 0.02275084143, 0.01706313107>] [1.0 rgb <0.2132891384, 0.02275084143, 0.01706313107>] } }
  finish { ambient 0.1832 diffuse 0.8168 phong 0.1 phong_size 40 } }
  no_shadow
  rotate <258.5796022, 311.7683734, 230.7185595>
  transform { Axis_Rotate_Trans(<0.3402260793, -0.5880731505, 0.7337684816>, 0 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
