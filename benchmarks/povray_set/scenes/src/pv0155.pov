// validation scene pv0155 (seed 155)
#version 3.7;
#declare NS = 1;
#declare NLT = 40;
#declare LINES = array[40] { 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56 };
#declare LR = 39570.58952692469;  // line rate, Hz
#declare TAU = 1.1668761393446649e-05;  // exposure, s
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
// film: 2464 x 4 samples spanning y/z in [-0.05383977612, 0.05627579708] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 1.703424942, 1398.530612>
  right <0, 154, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 17557.422
  pigment { function { max(0.002, min(0.98, 0.094342 * (1 + -0.298656 * ((y / 17557.422) - 0.00121801048) / 0.0550577866 + 0.151678 * sin(12.053248 * ((y / 17557.422) - 0.00121801048) / 0.0550577866 + 1.92256)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -183.5031472, 5241.226418> + 157237 * <0.6159158011, 0.6157001994, -0.4914885455> color rgb FL }
light_source { <0, -183.5031472, 5241.226418> + 157237 * <0.4336214338, 0.5355508716, 0.7246776636> color rgb FL * 0.6975 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, -183.5031472, 5241.226418>;  // mm
#declare V_0 = <-46133.12763, 5351.368009, -1016.283558>;  // mm/s
#declare TC_0 = 0.00123829340390947;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.7293444251, 0.7293444251, 0.7134891115>] [0.44 rgb <0.7293444251, 0.7293444251, 0.7134891115>] [0.46 rgb <0.5549359756, 0.6738508275, 0.1189148519>] [1.00 rgb <0.5549359756, 0.6738508275, 0.1189148519>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.5921 diffuse 0.4079 } }
  no_shadow
  rotate <259.8016499, 5.926090942, 346.3881047>
  transform { Axis_Rotate_Trans(<0.1454518767, -0.2111927401, 0.9665616266>, 13848.527 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
