// validation scene pv3828 (seed 3828)
#version 3.7;
#declare NS = 1;
#declare NLT = 113;
#declare LINES = array[113] { 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149 };
#declare LR = 183.5568033692135;  // line rate, Hz
#declare TAU = 0.00018530042905976553;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.336472 * sin(753.9822369 * T + 3.54141));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 2576 x 4 samples spanning y/z in [0.06177694345, 0.2260743939] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 141.0370799, 979.929996>
  right <0, 161, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 7550.9224
  pigment { function { max(0.002, min(0.98, 0.0990616 * (1 + -0.250887 * ((y / 7550.9224) - 0.1439256687) / 0.08214872525 + 0.070181 * sin(4.1931603 * ((y / 7550.9224) - 0.1439256687) / 0.08214872525 + 0.298525)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 190.652032, 1697.805685> + 50934.2 * <-0.03059503007, -0.2064780368, -0.9779727831> color rgb FL }

#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }

// ball 0: baseball
#declare C0_0 = <0, 190.652032, 1697.805685>;  // mm
#declare V_0 = <108.3481673, 73.54981585, -48.84146503>;  // mm/s
#declare TC_0 = 0.5556862950747357;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { function { (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05) * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }
    color_map { [0.0 rgb <0.8272458685, 0.8088626269, 0.7537129024>] [0.5 rgb <0.8272458685, 0.8088626269, 0.7537129024>] [0.5 rgb <0.689371557, 0.07353296608, 0.05514972456>] [1.0 rgb <0.689371557, 0.07353296608, 0.05514972456>] } }
  finish { ambient 0.1306 diffuse 0.8694 phong 0.1 phong_size 40 } }
  no_shadow
  rotate <176.0515382, 279.4151384, 11.88389876>
  transform { Axis_Rotate_Trans(<0.9846117689, 0.01145433473, 0.1743802247>, 34.938512 * (T - TC_0)) }
  scale 36.6
  translate P_0 }
#end
