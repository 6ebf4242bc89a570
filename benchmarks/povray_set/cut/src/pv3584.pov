// validation scene pv3584 (seed 3584)
#version 3.7;
#declare NS = 1;
#declare NLT = 71;
#declare LINES = array[71] { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70 };
#declare LR = 29461.142043053092;  // line rate, Hz
#declare TAU = 6.663223471983199e-06;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.326335 * sin(628.3185307 * T + 2.32667));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 2384 x 4 samples spanning y/z in [-0.2119505991, -0.07312352097] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -150.4001894, 1055.165509>
  right <0, 146.4855445, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 6069.2059
  pigment { function { max(0.002, min(0.98, 0.801577 * (1 + 0.089695 * ((y / 6069.2059) - -0.14253706) / 0.06941353907 + 0.229666 * sin(9.4247137 * ((y / 6069.2059) - -0.14253706) / 0.06941353907 + 0.983892)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -205.6521675, 1302.269803> + 39068.1 * <-0.4135165377, 0.5851972304, -0.6975301245> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, -205.6521675, 1302.269803>;  // mm
#declare V_0 = <-22769.52911, 1941.931805, 11821.23476>;  // mm/s
#declare TC_0 = 0.0008146323711731052;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.2328705941, 0.2328705941, 0.2278081898>] [0.44 rgb <0.2328705941, 0.2328705941, 0.2278081898>] [0.46 rgb <0.1771841477, 0.2151521793, 0.03796803164>] [1.00 rgb <0.1771841477, 0.2151521793, 0.03796803164>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.3538 diffuse 0.6462 } }
  no_shadow
  rotate <338.4080231, 173.7086346, 340.3932423>
  transform { Axis_Rotate_Trans(<-0.03193007995, -0.6905928962, 0.7225385262>, 13026.955 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
