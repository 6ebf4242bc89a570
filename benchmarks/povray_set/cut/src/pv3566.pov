// validation scene pv3566 (seed 3566)
#version 3.7;
#declare NS = 1;
#declare NLT = 72;
#declare LINES = array[72] { 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105 };
#declare LR = 62.11892836226787;  // line rate, Hz
#declare TAU = 0.0016621273480566469;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.11255 * sin(628.3185307 * T + 6.03528));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 2064 x 4 samples spanning y/z in [-0.0487287838, 0.04999432298] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 0.8270631589, 1307.052639>
  right <0, 129.0362972, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 22829.311
  pigment { function { max(0.002, min(0.98, 0.0424822 * (1 + 0.288172 * ((y / 22829.311) - 0.0006327695874) / 0.04936155339 + 0 * sin(4.1270798 * ((y / 22829.311) - 0.0006327695874) / 0.04936155339 + 0.942441)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -58.15751694, 4068.001792> + 122040 * <-0.3671078578, 0.07551126625, -0.9271083375> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, -58.15751694, 4068.001792>;  // mm
#declare V_0 = <-117.3488788, 3.774688937, 6.60315038>;  // mm/s
#declare TC_0 = 1.529324515161866;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.6678421722, 0.6678421722, 0.6678421722>] [0.925 rgb <0.6678421722, 0.6678421722, 0.6678421722>] [0.935 rgb <0.03629577023, 0.03629577023, 0.03629577023>] [1.0 rgb <0.03629577023, 0.03629577023, 0.03629577023>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.4115 diffuse 0.5885 phong 0.2517 phong_size 40 } }
  no_shadow
  rotate <354.9072037, 229.6840545, 10.71263029>
  transform { Axis_Rotate_Trans(<0.4972231873, 0.6976329119, -0.5158269305>, 93.130277 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
