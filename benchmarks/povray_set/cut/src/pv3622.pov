// validation scene pv3622 (seed 3622)
#version 3.7;
#declare NS = 1;
#declare NLT = 75;
#declare LINES = array[75] { 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126 };
#declare LR = 124.4637163580798;  // line rate, Hz
#declare TAU = 0.0003375253585121247;  // exposure, s
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
// film: 284 x 4 samples spanning y/z in [0.3584551995, 0.3718178785] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 2061.108085, 5644.759877>
  right <0, 75.42911419, 0>
  up <1, 0, 0>
  aperture 41.173103 blur_samples 19 focal_point <0, 3961.185724, 10848.505> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 42235.085
  pigment { function { max(0.002, min(0.98, 0.269173 * (1 + 0.398308 * ((y / 42235.085) - 0.365136539) / 0.006681339493 + 0.0399882 * sin(13.457187 * ((y / 42235.085) - 0.365136539) / 0.006681339493 + 4.61672)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 3024.745056, 8250.526082> + 247516 * <0.7023064097, 0.004695729218, -0.7118592958> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, 3024.745056, 8250.526082>;  // mm
#declare V_0 = <-49.00691549, -0.2192237883, -24.92182162>;  // mm/s
#declare TC_0 = 1.1248258054357192;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.7431799905, 0.7431799905, 0.7270239038>] [0.44 rgb <0.7431799905, 0.7431799905, 0.7270239038>] [0.46 rgb <0.5654630363, 0.6866336869, 0.1211706506>] [1.00 rgb <0.5654630363, 0.6866336869, 0.1211706506>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.4422 diffuse 0.5578 phong 0.4788 phong_size 40 } }
  no_shadow
  rotate <274.4409039, 97.32477034, 31.08070222>
  transform { Axis_Rotate_Trans(<0.6186191707, 0.6398552394, -0.4559556933>, 27.666859 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
