// validation scene pv3916 (seed 3916)
#version 3.7;
#declare NS = 1;
#declare NLT = 175;
#declare LINES = array[175] { 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 208, 209, 210, 211, 212, 213, 214, 215, 216, 217, 218, 219, 220, 221, 222, 223, 224 };
#declare LR = 477.86763862713286;  // line rate, Hz
#declare TAU = 0.0003794361881019852;  // exposure, s
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
// film: 616 x 4 samples spanning y/z in [-0.1433340079, -0.08014952272] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, -269.4752413, 2411.589261>
  right <0, 152.375026, 0>
  up <1, 0, 0>
  aperture 35.928268 blur_samples 19 focal_point <0, -458.8000592, 4105.8959> confidence 0.999 variance 0 }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 32932.501
  pigment { function { max(0.002, min(0.98, 0.0100909 * (1 + 0.333111 * ((y / 32932.501) - -0.1117417653) / 0.03159224261 + 0 * sin(22.505334 * ((y / 32932.501) - -0.1117417653) / 0.03159224261 + 6.24835)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -508.4818974, 5825.380743> + 174761 * <-0.03796561551, 0.2621606089, -0.9642771527> color rgb FL }


// ball 0: plain
#declare C0_0 = <0, -508.4818974, 5825.380743>;  // mm
#declare V_0 = <353.309852, 280.6165524, 12.87148287>;  // mm/s
#declare TC_0 = 0.2866902650984855;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.5018999127, 0.4070204204, 0.3053261227> }
  finish { ambient 0.2763 diffuse 0.7237 } }
  no_shadow
  rotate <10.05344293, 25.07587503, 176.3089523>
  transform { Axis_Rotate_Trans(<-0.1132576352, 0.6224302892, -0.774437372>, 47.085887 * (T - TC_0)) }
  scale 62.02902582
  translate P_0 }
#end
