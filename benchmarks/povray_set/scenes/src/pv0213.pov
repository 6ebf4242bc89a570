// validation scene pv0213 (seed 213)
#version 3.7;
#declare NS = 1;
#declare NLT = 29;
#declare LINES = array[29] { 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35 };
#declare LR = 867.4430003608034;  // line rate, Hz
#declare TAU = 6.15946668860598e-05;  // exposure, s
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
// film: 2832 x 4 samples spanning y/z in [-0.3878439872, -0.3198300834] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -1036.3536, 2928.900868>
  right <0, 199.2059818, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 15474.561
  pigment { function { max(0.002, min(0.98, 0.819839 * (1 + -0.154175 * ((y / 15474.561) - -0.3538370353) / 0.03400695189 + 0.0563354 * sin(10.243259 * ((y / 15474.561) - -0.3538370353) / 0.03400695189 + 2.0955)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -1475.350734, 4142.619338> + 124279 * <0.5562555986, -0.1551618393, -0.8163972762> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: tennis
#declare C0_0 = <0, -1475.350734, 4142.619338>;  // mm
#declare V_0 = <-2356.084373, -353.7230631, 1244.594818>;  // mm/s
#declare TC_0 = 0.0242090834686144;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { min(1, fSeamDist(x, y, z) / 0.2) }
    color_map { [0.00 rgb <0.1709012181, 0.1709012181, 0.1671859742>] [0.44 rgb <0.1709012181, 0.1709012181, 0.1671859742>] [0.46 rgb <0.1300335355, 0.1578978645, 0.02786432904>] [1.00 rgb <0.1300335355, 0.1578978645, 0.02786432904>] } }
  normal { bumps 0.25 scale 0.04 }
  finish { ambient 0.2065 diffuse 0.7935 } }
  no_shadow
  rotate <189.176194, 105.2858199, 69.72156491>
  transform { Axis_Rotate_Trans(<-0.7118710355, 0.5175229026, 0.474773287>, 0 * (T - TC_0)) }
  scale 33.5
  translate P_0 }
#end
