"""Timing of the renderer (run on demand, not part of the test suite).

    python benchmarks/bench_render.py [--repeats N]

Renders the reference case of the brief: a 2048 x 500 image of one tennis
ball (R = 33.5 mm, z = 3 m, f = 3000 px, 70 kHz, 30 m/s) on one core, and
prints the median time of several runs against the 0.3 s target.  As a
baseline it also times naive supersampling of every pixel (the same sample
kernel and pattern, no pixel classification) on a crop of a few lines
through the ball and scales it to the whole image.
"""

from __future__ import annotations

import os

# One core: set before numpy is imported so its thread pools start with one thread.
for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS", "NUMEXPR_NUM_THREADS"):
    os.environ[_var] = "1"

import argparse  # noqa: E402
import statistics  # noqa: E402
import time  # noqa: E402

import numpy as np  # noqa: E402

from ballscan.geometry.camera import LineScanCamera  # noqa: E402
from ballscan.geometry.motion import BallMotion  # noqa: E402
from ballscan.model.render import Appearance, RenderSettings, SensorNoise, _sample_pattern, _sample_pixels, apply_sensor, render  # noqa: E402

TARGET_S = 0.3
N_LINES = 500


def _scene() -> tuple[LineScanCamera, BallMotion]:
    cam = LineScanCamera(width=2048, focal_px=3000.0, principal_px=1023.5, line_rate_hz=70000.0)
    mo = BallMotion(0.0335, 0.5 * N_LINES / cam.line_rate_hz, (0.0, 0.05, 3.0), (30.0, 0.0, 0.0))
    return cam, mo


def _median_time(fn, repeats: int) -> float:
    fn()  # warm-up (imports, caches)
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


def _naive_full_image_s(cam: LineScanCamera, mo: BallMotion, app: Appearance, crop_lines: int) -> float:
    """Seconds to supersample every pixel of ``crop_lines`` lines through the ball, scaled to the image."""
    st = RenderSettings()
    pat = _sample_pattern(st.samples_along, st.samples_across, st.samples_time, st.sampling_seed, cam.focal_px, cam.exposure)
    t_lines = np.arange(N_LINES) / cam.line_rate_hz
    mid = N_LINES // 2
    lines = np.arange(mid - crop_lines // 2, mid - crop_lines // 2 + crop_lines)
    pl = np.repeat(lines, cam.width)
    pc = np.tile(np.arange(cam.width), lines.size)
    rot0 = [app.initial_rotation()]
    t0 = time.perf_counter()
    _sample_pixels(cam, (mo,), (app,), rot0, t_lines, pl, pc, pat, 0.1)
    return (time.perf_counter() - t0) * N_LINES / crop_lines


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=7, help="timed runs per case (median reported)")
    parser.add_argument("--crop-lines", type=int, default=4, help="lines of the naive baseline's crop")
    args = parser.parse_args(argv)

    cam, mo = _scene()
    noise = SensorNoise()
    cases = {
        "flat": Appearance.flat(),
        "lambertian": Appearance(),
        "tennis texture, spinning": Appearance(texture="tennis", spin_rps=50.0),
    }
    print(f"render 2048 x {N_LINES}, one tennis ball (R=33.5 mm, z=3 m, f=3000 px, 70 kHz, 30 m/s), one core")
    print(f"median of {args.repeats} runs; target {TARGET_S * 1e3:.0f} ms for the whole render incl. sensor noise\n")
    header = f"{'appearance':28s} {'clean (ms)':>11s} {'+noise (ms)':>12s} {'target':>8s} {'naive (ms)':>11s} {'speed-up':>9s}"
    print(header)
    print("-" * len(header))
    clean_img = None
    for name, app in cases.items():
        t_clean = _median_time(lambda: render(cam, (mo, app), N_LINES, noise=None), args.repeats)
        t_full = _median_time(lambda: render(cam, (mo, app), N_LINES, noise=noise, seed=1), args.repeats)
        t_naive = _naive_full_image_s(cam, mo, app, args.crop_lines)
        ok = "ok" if t_full <= TARGET_S else "SLOW"
        print(f"{name:28s} {t_clean * 1e3:11.1f} {t_full * 1e3:12.1f} {ok:>8s} {t_naive * 1e3:11.0f} {t_naive / t_full:8.0f}x")
        clean_img = render(cam, (mo, app), N_LINES, noise=None).clean
    t_noise = _median_time(lambda: apply_sensor(clean_img, noise, 1), args.repeats)
    print(f"\nsensor model alone (Poisson + read noise + PRNU, 2048 x {N_LINES}): {t_noise * 1e3:.1f} ms")
    print(f"naive baseline: every pixel x {RenderSettings().samples_per_pixel} samples on {args.crop_lines} lines, scaled to {N_LINES}")


if __name__ == "__main__":
    main()
