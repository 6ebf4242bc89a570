// validation scene pv0198 (seed 198)
#version 3.7;
#declare NS = 1;
#declare NLT = 32;
#declare LINES = array[32] { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31 };
#declare LR = 38.683810060645236;  // line rate, Hz
#declare TAU = 0.001764954823168538;  // exposure, s
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
// film: 1792 x 4 samples spanning y/z in [0.108542035, 0.2185590448] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 166.4984396, 1018.024396>
  right <0, 112, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 48141.725
  pigment { function { max(0.002, min(0.98, 0.0847109 * (1 + -0.277389 * ((y / 48141.725) - 0.1635505399) / 0.05500850491 + 0.22773 * sin(5.0465269 * ((y / 48141.725) - 0.1635505399) / 0.05500850491 + 2.24479)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 2438.611545, 12155.94365> + 364678 * <-0.3703311459, -0.305481574, -0.877231925> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, 2438.611545, 12155.94365>;  // mm
#declare V_0 = <-271.5084345, 1.310336899, -103.9753697>;  // mm/s
#declare TC_0 = 0.3360579006985012;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.6944499555, 0.6944499555, 0.6944499555>] [0.925 rgb <0.6944499555, 0.6944499555, 0.6944499555>] [0.935 rgb <0.03774184541, 0.03774184541, 0.03774184541>] [1.0 rgb <0.03774184541, 0.03774184541, 0.03774184541>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.2529 diffuse 0.7471 } }
  no_shadow
  rotate <135.6716572, 282.6912964, 251.4571848>
  transform { Axis_Rotate_Trans(<-0.8980036813, 0.4273752417, 0.1045934561>, 241.79978 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
