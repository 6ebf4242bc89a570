// validation scene pv0099 (seed 99)
#version 3.7;
#declare NS = 1;
#declare NLT = 73;
#declare LINES = array[73] { 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92 };
#declare LR = 159.2706971234738;  // line rate, Hz
#declare TAU = 0.0012709729467578535;  // exposure, s
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
// film: 2704 x 4 samples spanning y/z in [-0.07473393101, 0.06360978533] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -6.795591369, 1221.77317>
  right <0, 169.0246409, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 42755.615
  pigment { function { max(0.002, min(0.98, 0.0392876 * (1 + -0.134607 * ((y / 42755.615) - -0.005562072841) / 0.06917185817 + 0 * sin(14.419807 * ((y / 42755.615) - -0.005562072841) / 0.06917185817 + 3.76855)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 82.83694889, 8924.343146> + 267730 * <-0.6798143793, 0.2694205215, -0.682103359> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, 82.83694889, 8924.343146>;  // mm
#declare V_0 = <523.2307522, -760.2388722, -13.84514949>;  // mm/s
#declare TC_0 = 0.35160265517382827;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.8820657643, 0.8820657643, 0.8820657643>] [0.925 rgb <0.8820657643, 0.8820657643, 0.8820657643>] [0.935 rgb <0.04793835675, 0.04793835675, 0.04793835675>] [1.0 rgb <0.04793835675, 0.04793835675, 0.04793835675>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.2385 diffuse 0.7615 phong 0.2149 phong_size 40 } }
  no_shadow
  rotate <218.7915324, 268.2136259, 167.5279102>
  transform { Axis_Rotate_Trans(<-0.8004213209, -0.5980917138, 0.04014985509>, 0 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
