// validation scene pv0059 (seed 59)
#version 3.7;
#declare NS = 1;
#declare NLT = 43;
#declare LINES = array[43] { 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52 };
#declare LR = 4962.0602405664185;  // line rate, Hz
#declare TAU = 9.70361812031859e-06;  // exposure, s
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
// film: 436 x 4 samples spanning y/z in [-0.210619919, -0.1169535372] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -190.5993702, 1163.704608>
  right <0, 109, 0>
  up <1, 0, 0>
  aperture 14.121901 blur_samples 19 focal_point <0, -661.8094559, 4040.6782> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 13527.592
  pigment { function { max(0.002, min(0.98, 0.102655 * (1 + -0.164533 * ((y / 13527.592) - -0.1637867281) / 0.04683319086 + 0.0398566 * sin(13.966991 * ((y / 13527.592) - -0.1637867281) / 0.04683319086 + 3.02934)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -354.4747613, 2548.31741> + 76449.5 * <0.2959859365, 0.4529103637, -0.8409902067> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, -354.4747613, 2548.31741>;  // mm
#declare V_0 = <9734.322574, 1532.802211, -620.2101159>;  // mm/s
#declare TC_0 = 0.006247405008622256;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.7758430413, 0.7586020848, 0.7068792154>] [0.5 rgb <0.7758430413, 0.7586020848, 0.7068792154>] [0.5 rgb <0.6465358678, 0.0689638259, 0.05172286942>] [1.0 rgb <0.6465358678, 0.0689638259, 0.05172286942>] } }
  finish { ambient 0.5926 diffuse 0.4074 phong 0.1 phong_size 40 } }
  no_shadow
  rotate <237.203463, 253.5345603, 292.3321983>
  transform { Axis_Rotate_Trans(<-0.3858874452, 0.8064075529, 0.4481046064>, 0 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
