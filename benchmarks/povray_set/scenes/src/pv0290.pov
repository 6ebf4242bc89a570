// validation scene pv0290 (seed 290)
#version 3.7;
#declare NS = 1;
#declare NLT = 45;
#declare LINES = array[45] { 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55 };
#declare LR = 154.40965653769186;  // line rate, Hz
#declare TAU = 0.0003411963736336865;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.116865 * sin(628.3185307 * T + 1.34768));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 3056 x 4 samples spanning y/z in [-0.09904758822, 0.1108547461] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 5.357474979, 907.4961209>
  right <0, 190.4855541, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 19366.927
  pigment { function { max(0.002, min(0.98, 0.102748 * (1 + 0.12855 * ((y / 19366.927) - 0.005903578931) / 0.1049511672 + 0.0871659 * sin(4.0224906 * ((y / 19366.927) - 0.005903578931) / 0.1049511672 + 3.10777)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -112.7829831, 4932.9955> + 147990 * <-0.4695143568, -0.5332662161, -0.7036926968> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, -112.7829831, 4932.9955>;  // mm
#declare V_0 = <-846.941475, -105.6268712, -31.38912381>;  // mm/s
#declare TC_0 = 0.21371720357362883;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.8970372855, 0.8970372855, 0.8970372855>] [0.925 rgb <0.8970372855, 0.8970372855, 0.8970372855>] [0.935 rgb <0.04875202638, 0.04875202638, 0.04875202638>] [1.0 rgb <0.04875202638, 0.04875202638, 0.04875202638>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.3381 diffuse 0.6619 phong 0.5016 phong_size 40 } }
  no_shadow
  rotate <218.0134415, 238.7722578, 88.90536424>
  transform { Axis_Rotate_Trans(<-0.2961798687, -0.3682631234, 0.8812830177>, 0 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
