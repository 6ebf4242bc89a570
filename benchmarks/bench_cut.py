"""Balls cut by a sensor end or an image end: measured, and are their sigmas honest?  (run on demand; the tests use ``cut_scene``)

    python benchmarks/bench_cut.py [--seeds N] [--visible LO,HI] [--cases col0,colW,first,last] [--vz-max V]

Each case renders ``--seeds`` images (seeded) of a tennis ball (R = 33.5 mm)
2 m from a 256-pixel camera (f = 2000 px, 20 kHz: 67 px wide, 134 lines at
10 m/s) on the default 8-bit sensor, cut by pixel 0 (``col0``), by pixel
W-1 (``colW``), by the first line (``first``) or by the last line
(``last``), with a random share of its diameter in ``--visible`` seen and
random ``V.y`` (+-1 m/s) and ``V.z`` (+-1.5 m/s, or ``--vz-max``).  It prints per case: the
balls measured (no key undetermined), those with an undetermined key, the
largest ``|z|`` of the speed (``z = (estimate - truth) / sigma``), the
1-sigma coverage of the speed and of each of the six fitted parameters,
and the median relative sigma of the speed and of ``V.z``.
"""

from __future__ import annotations

import argparse
import math
import time

import numpy as np

from ballscan.geometry.camera import LineScanCamera
from ballscan.geometry.motion import BallMotion
from ballscan.model.render import Appearance, render
from ballscan.pipeline.estimate import estimate_image

CAMERA = LineScanCamera(256, 2000.0, 127.5, 20000.0)
RADIUS_M = 0.0335
Z0_M = 2.0
VX_MPS = 10.0
CASES = ("col0", "colW", "first", "last")
#: the flag each cut gets
CUT_FLAG = {"col0": "cut_sensor_end", "colW": "cut_sensor_end", "first": "cut_first_line", "last": "cut_last_line"}
PARAMS = ("t_c", "y0", "z0", "vx", "vy", "vz")


def cut_scene(case: str, visible: float, seed: int, vy: float = 0.6, vz: float = -0.8, n_lines: int = 200):
    """The true motion and the rendered image (DN, 8 bit) of a ball cut by ``case`` with ``visible`` of its diameter seen.

    ``visible`` is the share of the diameter inside the sensor (``col0``,
    ``colW``: at the crossing) or of the ball's time across the viewing
    plane inside the image (``first``, ``last``).
    """
    cam = CAMERA
    r_px = cam.focal_px * RADIUS_M / Z0_M
    transit = 2 * RADIUS_M / VX_MPS
    y0, t_c = 0.0, 0.5 * (n_lines - 1) / cam.line_rate_hz
    if case == "col0":
        y0 = ((2 * visible - 1) * r_px - 0.5 - cam.principal_px) * Z0_M / cam.focal_px
    elif case == "colW":
        y0 = ((cam.width - 0.5) - (2 * visible - 1) * r_px - cam.principal_px) * Z0_M / cam.focal_px
    elif case == "first":
        t_c = (visible - 0.5) * transit
    elif case == "last":
        t_c = (n_lines - 1) / cam.line_rate_hz - (visible - 0.5) * transit
    else:
        raise ValueError(f"case: expected one of {', '.join(CASES)}, got {case!r}")
    m = BallMotion(RADIUS_M, t_c, (0.0, y0, Z0_M), (VX_MPS, vy, vz))
    return m, render(cam, [(m, Appearance(ball_level=0.7))], n_lines, seed=seed).image


def draw(seed: int, visible_range: tuple[float, float], vz_max: float = 1.5) -> tuple[float, float, float]:
    """The seeded visible share, ``V.y`` (+-1 m/s) and ``V.z`` (+-``vz_max``) of render ``seed``."""
    rng = np.random.default_rng(1000 + seed)
    return rng.uniform(*visible_range), rng.uniform(-1.0, 1.0), rng.uniform(-vz_max, vz_max)


def measure(case: str, seed: int, visible_range: tuple[float, float], vz_max: float = 1.5) -> dict:
    """One render of ``case`` measured: the speed's and the parameters' z, or what was undetermined."""
    visible, vy, vz = draw(seed, visible_range, vz_max)
    m, image = cut_scene(case, visible, seed, vy, vz)
    (ball,) = estimate_image(image, CAMERA, RADIUS_M).balls
    rec = {"visible": visible, "flags": ball.flags, "undetermined": ball.undetermined}
    if not ball.undetermined:
        est = np.array([ball.t_c_s, *ball.position_m[1:], *ball.velocity_mps])
        sig = np.array([ball.t_c_sigma_s, *ball.position_sigma_m[1:], *ball.velocity_sigma_mps])
        rec["z_params"] = (est - m.to_params()) / sig
        rec["z_speed"] = (ball.speed_mps - m.speed_mps) / ball.speed_sigma_mps
        rec["speed_rel_sigma"] = ball.speed_sigma_mps / m.speed_mps
        rec["vz_sigma"] = ball.velocity_sigma_mps[2]
    return rec


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", type=int, default=20)
    ap.add_argument("--visible", default="0.4,0.7", help="range of the visible share of the diameter")
    ap.add_argument("--cases", default=",".join(CASES))
    ap.add_argument("--vz-max", type=float, default=1.5, help="V.z drawn within +-this, m/s (V.x is 10 m/s)")
    a = ap.parse_args(argv)
    lo, hi = (float(v) for v in a.visible.split(","))
    print(f"{a.seeds} renders per case, {lo:.0%}-{hi:.0%} of the diameter seen, |V.z| <= {a.vz_max:g} m/s")
    print(f"{'case':6} {'measured':>8} {'undet.':>6} {'max|z|':>7} {'speed':>6} " + " ".join(f"{p:>5}" for p in PARAMS) + f" {'sig_s/V':>8} {'sig_vz':>7}  s")
    for case in a.cases.split(","):
        t0 = time.perf_counter()
        recs = [measure(case, s, (lo, hi), a.vz_max) for s in range(a.seeds)]
        ok = [r for r in recs if "z_speed" in r]
        zs = np.abs([r["z_speed"] for r in ok]) if ok else np.array([math.nan])
        zp = np.abs([r["z_params"] for r in ok]) if ok else np.full((1, 6), math.nan)
        cover = " ".join(f"{np.mean(zp[:, k] < 1):5.2f}" for k in range(6))
        med_s = np.median([r["speed_rel_sigma"] for r in ok]) if ok else math.nan
        med_vz = np.median([r["vz_sigma"] for r in ok]) if ok else math.nan
        print(f"{case:6} {len(ok):8d} {len(recs) - len(ok):6d} {zs.max():7.2f} {np.mean(zs < 1):6.2f} {cover} {med_s:8.1%} {med_vz:7.2f} {time.perf_counter() - t0:3.0f}")


if __name__ == "__main__":
    main()
