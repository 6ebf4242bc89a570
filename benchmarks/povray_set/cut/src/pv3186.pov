// validation scene pv3186 (seed 3186)
#version 3.7;
#declare NS = 2;
#declare NLT = 137;
#declare LINES = array[137] { 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174 };
#declare LR = 1801.537890694248;  // line rate, Hz
#declare TAU = 0.0005325727940802156;  // exposure, s
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
// film: 732 x 4 samples spanning y/z in [-0.2181659458, -0.1436937888] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -456.1204143, 2520.979102>
  right <0, 187.7427515, 0>
  up <1, 0, 0>
  aperture 200.28426 blur_samples 19 focal_point <0, -2864.123127, 15830.018> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 74294.757
  pigment { function { max(0.002, min(0.98, 0.0453738 * (1 + 0.0991636 * ((y / 74294.757) - -0.1809298673) / 0.0372360785 + 0 * sin(7.3510599 * ((y / 74294.757) - -0.1809298673) / 0.0372360785 + 6.08382)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -1822.522414, 12689.97171> + 380699 * <0.4660567435, 0.4297211738, -0.7733891805> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: football
#declare C0_0 = <0, -1822.522414, 12689.97171>;  // mm
#declare V_0 = <-3083.272742, -476.6397072, -1546.858709>;  // mm/s
#declare TC_0 = 0.0588386181315073;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { max((0.000000*x + -0.525731*y + -0.850651*z)/fRad(x,y,z), (-0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + -0.525731*y + 0.850651*z)/fRad(x,y,z), (-0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + -0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + -0.850651*z)/fRad(x,y,z), (0.525731*x + -0.850651*y + 0.000000*z)/fRad(x,y,z), (-0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z), (0.000000*x + 0.525731*y + 0.850651*z)/fRad(x,y,z), (0.525731*x + 0.850651*y + 0.000000*z)/fRad(x,y,z), (0.850651*x + 0.000000*y + 0.525731*z)/fRad(x,y,z)) }
    color_map { [0.0 rgb <0.8376280639, 0.8376280639, 0.8376280639>] [0.925 rgb <0.8376280639, 0.8376280639, 0.8376280639>] [0.935 rgb <0.04552326434, 0.04552326434, 0.04552326434>] [1.0 rgb <0.04552326434, 0.04552326434, 0.04552326434>] } }
  normal { bumps 0.1 scale 0.05 }
  finish { ambient 0.223 diffuse 0.777 } }
  no_shadow
  rotate <216.8613099, 91.54621008, 116.2058646>
  transform { Axis_Rotate_Trans(<0.7706946365, 0.07661772368, -0.6325816166>, 0 * (T - TC_0)) }
  scale 110
  translate P_0 }
#end
