// validation scene pv3772 (seed 3772)
#version 3.7;
#declare NS = 1;
#declare NLT = 93;
#declare LINES = array[93] { 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118 };
#declare LR = 20.0;  // line rate, Hz
#declare TAU = 0.0036466622729149313;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.134724 * sin(628.3185307 * T + 2.61406));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 1104 x 4 samples spanning y/z in [0.3137766284, 0.3808739125] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 329.6195123, 949.0225455>
  right <0, 63.67683536, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 63539.282
  pigment { function { max(0.002, min(0.98, 0.0120946 * (1 + 0.188737 * ((y / 63539.282) - 0.3473252705) / 0.03354864205 + 0 * sin(19.214383 * ((y / 63539.282) - 0.3473252705) / 0.03354864205 + 2.78399)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 3339.539376, 10630.97318> + 318929 * <-0.11007354, -0.5568143729, -0.8233113445> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, 3339.539376, 10630.97318>;  // mm
#declare V_0 = <51.5173782, 1.503848489, -10.96155895>;  // mm/s
#declare TC_0 = 3.6;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.736656315, 0.736656315, 0.736656315>] [0.925 rgb <0.736656315, 0.736656315, 0.736656315>] [0.935 rgb <0.04003566929, 0.04003566929, 0.04003566929>] [1.0 rgb <0.04003566929, 0.04003566929, 0.04003566929>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.3579 diffuse 0.6421 } }
  no_shadow
  rotate <156.6594551, 198.5033882, 100.9831552>
  transform { Axis_Rotate_Trans(<0.4160920085, -0.8172298187, -0.3987516318>, 13.172386 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
