// validation scene pv4280 (seed 4280)
#version 3.7;
#declare NS = 1;
#declare NLT = 139;
#declare LINES = array[139] { 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177 };
#declare LR = 10117.109581767134;  // line rate, Hz
#declare TAU = 3.122814688563513e-06;  // exposure, s
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
// film: 428 x 4 samples spanning y/z in [-0.05286960577, 0.02384120594] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -20.24511743, 1394.849013>
  right <0, 107, 0>
  up <1, 0, 0>
  aperture 12.516222 blur_samples 19 focal_point <0, -45.2452536, 3117.3095> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 14814.276
  pigment { function { max(0.002, min(0.98, 0.538552 * (1 + 0.351764 * ((y / 14814.276) - -0.01451419992) / 0.03835540586 + 0.184447 * sin(7.6521849 * ((y / 14814.276) - -0.01451419992) / 0.03835540586 + 5.85867)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 97.92200923, 5086.102694> + 152583 * <-0.6955085974, -0.05459519606, -0.7164406155> color rgb FL }
light_source { <0, 97.92200923, 5086.102694> + 152583 * <0.5718394848, -0.7699968062, 0.2830274227> color rgb FL * 0.3409 }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, 97.92200923, 5086.102694>;  // mm
#declare V_0 = <-16809.96978, 7110.764771, -6021.346235>;  // mm/s
#declare TC_0 = 0.010674985689058423;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.1370386804, 0.1370386804, 0.1370386804>] [0.925 rgb <0.1370386804, 0.1370386804, 0.1370386804>] [0.935 rgb <0.007447754372, 0.007447754372, 0.007447754372>] [1.0 rgb <0.007447754372, 0.007447754372, 0.007447754372>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.4051 diffuse 0.5949 } }
  no_shadow
  rotate <261.5492987, 72.07230908, 171.3843382>
  transform { Axis_Rotate_Trans(<0.003853546009, -0.7441037993, 0.6680529067>, 4799.2223 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
