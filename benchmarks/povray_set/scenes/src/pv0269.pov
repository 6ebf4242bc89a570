// validation scene pv0269 (seed 269)
#version 3.7;
#declare NS = 1;
#declare NLT = 94;
#declare LINES = array[94] { 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144 };
#declare LR = 5694.374595261326;  // line rate, Hz
#declare TAU = 2.3819412190647462e-05;  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = (BGONLY ? 1 : 1 + 0.238259 * sin(628.3185307 * T + 4.64734));
global_settings { assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: 404 x 4 samples spanning y/z in [0.05185996392, 0.07034116012] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 333.9154402, 5465.014218>
  right <0, 101, 0>
  up <1, 0, 0>
  aperture 56.763194 blur_samples 19 focal_point <0, 645.1374133, 10558.617> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 64027.615
  pigment { function { max(0.002, min(0.98, 0.203793 * (1 + -0.161819 * ((y / 64027.615) - 0.06110056202) / 0.009240598099 + 0.0187147 * sin(13.211634 * ((y / 64027.615) - 0.06110056202) / 0.009240598099 + 5.39727)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, 808.809588, 13436.791> + 403104 * <-0.1036168096, 0.5174642511, -0.8494082091> color rgb FL }
light_source { <0, 808.809588, 13436.791> + 403104 * <-0.7361085707, 0.6576705999, -0.1600423509> color rgb FL * 0.2815 }


// ball 0: pingpong
#declare C0_0 = <0, 808.809588, 13436.791>;  // mm
#declare V_0 = <1393.253882, 67.38792284, -786.1262983>;  // mm/s
#declare TC_0 = 0.024410055516135395;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.6765917366, 0.6765917366, 0.6765917366> }
  finish { ambient 0.2393 diffuse 0.7607 phong 0.3728 phong_size 40 } }
  no_shadow
  rotate <234.5692131, 201.9823776, 138.073958>
  transform { Axis_Rotate_Trans(<-0.8259789937, -0.406523019, 0.3905095863>, 556.92843 * (T - TC_0)) }
  scale 20
  translate P_0 }
#end
