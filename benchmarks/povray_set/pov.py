"""POV-Ray source of a scene: one animation frame per (scan line, exposure sub-frame).

The POV-Ray frame is the camera frame of geometry.md in millimetres.  The film
is ``16 W`` samples along the sensor (``y``) by 4 across the line (``x``, one
pixel footprint ``|x| <= z / (2 f)``) on a pin-hole camera whose film spans the
*undistorted* normalised coordinates of the whole sensor; the assembly
(``render.py``) averages the samples of each distorted pixel (geometry.md's
radial model) and the sub-frames of each line.  The last frame of the
animation is the background alone at full lamp power (no flicker), used for
the lines no ball reaches.
"""

from __future__ import annotations

import math

import numpy as np

from scene import Scene, Ball

__all__ = ["film_range", "pov_source", "ini_source", "frame_count", "samples_along", "SAMPLES_ALONG", "SAMPLES_ACROSS", "BLUR_SAMPLES"]

SAMPLES_ALONG = 16
SAMPLES_ACROSS = 4
#: With focal blur POV-Ray jitters each ray inside its film sample, so fewer samples along the line do.
SAMPLES_ALONG_BLUR = 4
#: 19 rays a film sample: POV-Ray's 19-point hexagonal aperture grid (radius 0.385 plus jitter 0.096 of
#: its unit disc of radius 0.5), which covers the aperture disc.
BLUR_SAMPLES = 19
#: POV-Ray places the aperture rays at ``aperture / 2`` times its grid, whose disc has radius 0.5: the
#: lens's diameter is half the keyword's value.
POV_APERTURE_PER_DIAMETER = 2.0


def samples_along(scene: Scene) -> int:
    """Film samples per pixel along the sensor."""
    return SAMPLES_ALONG_BLUR if scene.optics.aperture_m > 0 else SAMPLES_ALONG

_SEAM = """#declare SeamK = 1.6;
#declare fRad = function(x, y, z) { sqrt(x*x + y*y + z*z) }
#declare fG = function(X, Y, Z) { Z - SeamK*(X*X - Y*Y) }
#declare fGs = function(X, Y, Z) {
  sqrt(max(4*SeamK*SeamK*(X*X + Y*Y) + 1 - pow(-2*SeamK*X*X + 2*SeamK*Y*Y + Z, 2), 1e-12)) }
#declare fSeamDist = function(x, y, z) {
  abs(fG(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z))) / fGs(x/fRad(x,y,z), y/fRad(x,y,z), z/fRad(x,y,z)) }
"""


def undistort(nd: float, k1: float, k2: float) -> float:
    """Invert n_d = n (1 + k1 n^2 + k2 n^4) (geometry.md) by Newton's method."""
    n = nd
    for _ in range(30):
        g = n * (1 + k1 * n * n + k2 * n**4) - nd
        dg = 1 + 3 * k1 * n * n + 5 * k2 * n**4
        n -= g / dg
    return n


def film_range(scene: Scene) -> tuple[float, float]:
    """Undistorted normalised coordinates (y / z) of the sensor's outer pixel edges u = -0.5 and W - 0.5."""
    cam = scene.camera
    lo = undistort((-0.5 - cam.principal_px) / cam.focal_px, cam.k1, cam.k2)
    hi = undistort((cam.width - 0.5 - cam.principal_px) / cam.focal_px, cam.k1, cam.k2)
    return lo, hi


def frame_count(scene: Scene) -> int:
    """Frames of the animation: traced lines x sub-frames, plus the background frame."""
    return len(scene.traced_lines) * scene.subframes + 1


def _vec(v, scale: float = 1.0) -> str:
    return "<" + ", ".join(f"{scale * float(a):.10g}" for a in v) + ">"


def _pigment(ball: Ball) -> str:
    a = ball.albedo_scale
    rgb = _vec(ball.rgb, a)
    if ball.kind == "tennis":
        white = _vec((0.92, 0.92, 0.90), a)
        return (f"pigment {{ function {{ min(1, fSeamDist(x, y, z) / 0.2) }}\n"
                f"    color_map {{ [0.00 rgb {white}] [0.44 rgb {white}] [0.46 rgb {rgb}] [1.00 rgb {rgb}] }} }}\n"
                f"  normal {{ bumps 0.25 scale 0.04 }}")
    if ball.kind == "baseball":
        red = _vec((0.75, 0.08, 0.06), a)
        return (f"pigment {{ function {{ (fSeamDist(x, y, z) < 0.018) + (fSeamDist(x, y, z) > 0.05)"
                f" * (fSeamDist(x, y, z) < 0.12) * (sin(54 * atan2(y, x)) > 0.2) }}\n"
                f"    color_map {{ [0.0 rgb {rgb}] [0.5 rgb {rgb}] [0.5 rgb {red}] [1.0 rgb {red}] }} }}")
    if ball.kind == "golf":
        return f"pigment {{ rgb {rgb} }}\n  normal {{ leopard 0.5 scale 0.07 }}"
    if ball.kind == "football":
        black = _vec((0.05, 0.05, 0.05), a)
        verts = _icosahedron()
        dots = ", ".join(f"({v[0]:.6f}*x + {v[1]:.6f}*y + {v[2]:.6f}*z)/fRad(x,y,z)" for v in verts)
        return (f"pigment {{ function {{ max({dots}) }}\n"
                f"    color_map {{ [0.0 rgb {rgb}] [0.925 rgb {rgb}] [0.935 rgb {black}] [1.0 rgb {black}] }} }}\n"
                f"  normal {{ bumps 0.1 scale 0.05 }}")
    return f"pigment {{ rgb {rgb} }}"


def _icosahedron() -> np.ndarray:
    p = (1 + math.sqrt(5)) / 2
    v = []
    for s1 in (-1, 1):
        for s2 in (-1, 1):
            v += [(0, s1, s2 * p), (s1, s2 * p, 0), (s2 * p, 0, s1)]
    a = np.asarray(v, float)
    return a / np.linalg.norm(a, axis=1)[:, None]


def _ball_block(ball: Ball, i: int, ambient: float) -> str:
    c0 = _vec(ball.position_m, 1000.0)
    v = _vec(ball.velocity_mps, 1000.0)
    phong = f" phong {ball.phong:.4g} phong_size 40" if ball.phong > 0 else ""
    return f"""// ball {i}: {ball.kind}
#declare C0_{i} = {c0};  // mm
#declare V_{i} = {v};  // mm/s
#declare TC_{i} = {ball.t_c_s!r};  // s
#declare P_{i} = C0_{i} + V_{i} * (T - TC_{i});
#if (BGONLY = 0)
sphere {{ <0, 0, 0>, 1
  texture {{
  {_pigment(ball)}
  finish {{ ambient {ambient:.4g} diffuse {1 - ambient:.4g}{phong} }} }}
  no_shadow
  rotate {_vec(ball.orientation_deg)}
  transform {{ Axis_Rotate_Trans({_vec(ball.spin_axis)}, {360.0 * ball.spin_rps:.8g} * (T - TC_{i})) }}
  scale {1000.0 * ball.radius_m:.10g}
  translate P_{i} }}
#end
"""


def pov_source(scene: Scene) -> str:
    """The whole .pov file of a scene."""
    cam, light = scene.camera, scene.light
    lo, hi = film_range(scene)
    f = cam.focal_px
    lines = ", ".join(str(i) for i in scene.traced_lines)
    z_ref = 1000.0 * scene.balls[0].position_m[2]
    lamp_dist = 30.0 * z_ref
    center = _vec(scene.balls[0].position_m, 1000.0)
    lamps = f"light_source {{ {center} + {lamp_dist:.6g} * {_vec(light.main_dir)} color rgb FL }}\n"
    if light.second_dir is not None:
        lamps += (f"light_source {{ {center} + {lamp_dist:.6g} * {_vec(light.second_dir)}"
                  f" color rgb FL * {light.second_intensity:.4g} }}\n")
    n_mid, n_half = 0.5 * (lo + hi), 0.5 * (hi - lo)
    blur = ""
    if scene.optics.aperture_m > 0:
        blur = (f"\n  aperture {POV_APERTURE_PER_DIAMETER * 1000.0 * scene.optics.aperture_m:.8g}"
                f" blur_samples {BLUR_SAMPLES}"
                f" focal_point <0, {1000.0 * scene.optics.focus_m * n_mid:.10g}, {1000.0 * scene.optics.focus_m:.8g}>"
                f" confidence 0.999 variance 0")
    zb = 1000.0 * light.background_distance_m
    bg = (f"{light.background_level:.6g} * (1 + {light.background_ramp:.6g} * ((y / {zb:.8g}) - {n_mid:.10g}) / {n_half:.10g}"
          f" + {light.background_wave:.6g} * sin({2 * math.pi * light.background_wave_periods:.8g}"
          f" * ((y / {zb:.8g}) - {n_mid:.10g}) / {n_half:.10g} + {light.background_wave_phase_rad:.6g}))")
    flicker = (f"1 + {light.flicker_depth:.6g} * sin({2 * math.pi * light.flicker_hz:.10g} * T + {light.flicker_phase_rad:.6g})"
               if light.flicker_hz else "1")
    need_seam = any(b.kind in ("tennis", "baseball", "football") for b in scene.balls)
    balls = "".join(_ball_block(b, i, light.ambient) for i, b in enumerate(scene.balls))
    return f"""// validation scene {scene.name} (seed {scene.seed})
#version 3.7;
#declare NS = {scene.subframes};
#declare NLT = {len(scene.traced_lines)};
#declare LINES = array[{len(scene.traced_lines)}] {{ {lines} }};
#declare LR = {cam.line_rate_hz!r};  // line rate, Hz
#declare TAU = {cam.exposure_s!r};  // exposure, s
#declare BGONLY = (frame_number >= NLT * NS);
#if (BGONLY)
  #declare T = 0;
#else
  #declare LINE = LINES[div(frame_number, NS)];
  #declare KS = mod(frame_number, NS);
  // mid-point of sub-interval KS of [t_i - tau/2, t_i + tau/2]
  #declare T = LINE / LR + TAU * ((KS + 0.5) / NS - 0.5);
#end
#declare FL = {"1" if not light.flicker_hz else f"(BGONLY ? 1 : {flicker})"};
global_settings {{ assumed_gamma 1.0 ambient_light rgb FL max_trace_level 5 }}
#include "transforms.inc"
// camera frame = POV frame: x across the line, y along the sensor, z forward
// film: {samples_along(scene) * cam.width} x {SAMPLES_ACROSS} samples spanning y/z in [{lo:.10g}, {hi:.10g}] and one pixel in x
camera {{ perspective location <0, 0, 0>
  direction <0, {f * n_mid:.10g}, {f:.10g}>
  right <0, {f * (hi - lo):.10g}, 0>
  up <1, 0, 0>{blur} }}
background {{ rgb 0 }}
// backdrop: self-lit, its level varies along the sensor, lit by the same (flickering) mains
plane {{ z, {zb:.8g}
  pigment {{ function {{ max(0.002, min(0.98, {bg})) }} }}
  finish {{ ambient 1 diffuse 0 }} }}
{lamps}
{_SEAM if need_seam else ""}
{balls}"""


def ini_source(scene: Scene) -> str:
    """The .ini: 16-bit linear PPM frames, no anti-aliasing (the film is the sample grid)."""
    return f"""; validation scene {scene.name}
Input_File_Name={scene.name}.pov
Output_File_Name=frames/{scene.name}_
Width={samples_along(scene) * scene.camera.width}
Height={SAMPLES_ACROSS}
Initial_Frame=0
Final_Frame={frame_count(scene) - 1}
Initial_Clock=0
Final_Clock=1
Output_File_Type=P
Bits_Per_Color=16
File_Gamma=1.0
Antialias=off
Display=off
Verbose=off
Warning_Level=0
"""
