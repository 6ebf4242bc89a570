// validation scene pv3482 (seed 3482)
#version 3.7;
#declare NS = 2;
#declare NLT = 157;
#declare LINES = array[157] { 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 189, 190, 191, 192, 193, 194, 195, 196, 197, 198, 199, 200 };
#declare LR = 521.3572026969064;  // line rate, Hz
#declare TAU = 0.0014140181906452615;  // exposure, s
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
// film: 2320 x 4 samples spanning y/z in [-0.0103856225, 0.01488677588] and one pixel in x
camera { perspective location <0, 0, 0>
  direction <0, 12.91325919, 5737.755686>
  right <0, 145.0068475, 0>
  up <1, 0, 0> }
background { rgb 0 }
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane { z, 5385.0815
  pigment { function { max(0.002, min(0.98, 0.0355489 * (1 + -0.331497 * ((y / 5385.0815) - 0.002250576688) / 0.01263619919 + 0.102348 * sin(15.9077 * ((y / 5385.0815) - 0.002250576688) / 0.01263619919 + 2.23342)))) } }
  finish { ambient 1 diffuse 0 } }
light_source { <0, -26.41334088, 2462.3368> + 73870.1 * <0.1606816398, 0.9580000702, -0.2375232116> color rgb FL }
light_source { <0, -26.41334088, 2462.3368> + 73870.1 * <-0.6299100537, 0.7516092952, -0.1956956607> color rgb FL * 0.2033 }


// ball 0: plain
#declare C0_0 = <0, -26.41334088, 2462.3368>;  // mm
#declare V_0 = <-78.25937433, -9.218727583, 3.806392511>;  // mm/s
#declare TC_0 = 0.23400463131402313;  // s
#declare P_0 = C0_0 + V_0 * (T - TC_0);
#if (BGONLY = 0)
sphere { <0, 0, 0>, 1
  texture {
  pigment { rgb <0.2909356714, 0.2386751748, 0.7640726748> }
  finish { ambient 0.135 diffuse 0.865 } }
  no_shadow
  rotate <203.5036281, 176.8006141, 272.2694824>
  transform { Axis_Rotate_Trans(<0.1471729591, -0.3689645134, 0.9177174445>, 65.754527 * (T - TC_0)) }
  scale 11.16421559
  translate P_0 }
#end
