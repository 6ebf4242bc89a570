"""Accuracy and run time of the paper's method (initial guess and Powell refinement).

Run on demand: ``python benchmarks/bench_paper.py [--trials N]``.  Renders a
fixed set of scenes (untextured and textured, bright and dark balls, several
geometries) with 8-bit sensor noise, estimates each with ``method="paper"``
and prints the median relative speed error of the initial guess (Eq. (3)-(7))
and of the refinement (Eq. (9)-(10)), and the median run time per ball on one
core.
"""

from __future__ import annotations

import os

os.environ.setdefault("OMP_NUM_THREADS", "1")
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import argparse
import statistics
import time


from ballscan.geometry.camera import LineScanCamera
from ballscan.pipeline.estimate import estimate_image
from ballscan.pipeline.recipe import Recipe
from ballscan.measure.images import LineImage
from ballscan.geometry.motion import BallMotion
from ballscan.model.render import Appearance, SensorNoise, render

SCENES = {
    "tennis 30 m/s perpendicular": (LineScanCamera(2048, 3000.0, 1023.5, 50000.0), BallMotion(0.0335, 0.0015, (0, 0.02, 3.0), (30.0, 0, 0)), 150),
    "tennis 30 m/s, 30 deg along sensor": (LineScanCamera(2048, 3000.0, 1023.5, 50000.0), BallMotion(0.0335, 0.0015, (0, 0.02, 3.0), (25.98, 15.0, 0)), 150),
    "tennis 29 m/s, receding 15 deg": (LineScanCamera(2048, 3000.0, 1023.5, 50000.0), BallMotion(0.0335, 0.0015, (0, 0.02, 3.0), (28.0, 0.0, 7.5)), 150),
    "table tennis 12.4 m/s": (LineScanCamera(1024, 2800.0, 511.5, 30000.0), BallMotion(0.02, 0.0036, (0, -0.04, 1.8), (12.37, 0.0, 0.0)), 220),
    "football 6 m/s, 2 kHz": (LineScanCamera(2048, 2500.0, 1023.5, 2000.0), BallMotion(0.11, 0.025, (0, 0.05, 4.0), (6.0, 0.5, 0.0)), 100),
}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--trials", type=int, default=3, help="noise seeds per scene and appearance")
    a = ap.parse_args()
    print(f"{'scene':38s} {'appearance':22s} {'initial err %':>13s} {'refined err %':>13s} {'time/ball s':>11s} {'evals':>6s}")
    all_i, all_r, all_t = [], [], []
    for name, (cam, m, n) in SCENES.items():
        for app_name, app, bg in (
            ("flat bright", Appearance.flat(0.8), 0.1),
            ("flat dark", Appearance.flat(0.05), 0.6),
            ("shaded tennis texture", Appearance(ball_level=0.65, texture="tennis", seam_level=0.95, orientation_seed=4), 0.1),
        ):
            ei, er, tt, ev = [], [], [], []
            for seed in range(a.trials):
                r = render(cam, (m, app), n, background_level=bg, noise=SensorNoise(), seed=seed)
                img = LineImage(r.image.astype(float), 255.0, 8, name)
                t0 = time.perf_counter()
                balls = estimate_image(img, cam, m.radius_m, recipe=Recipe(method="paper")).balls
                dt = time.perf_counter() - t0
                if len(balls) != 1:
                    print(f"  {name} {app_name} seed {seed}: {len(balls)} balls found")
                    continue
                b = balls[0]
                ei.append(abs(b.initial.speed_mps / m.speed_mps - 1) * 100)
                er.append(abs(b.speed_mps / m.speed_mps - 1) * 100)
                tt.append(dt)
                ev.append(b.extra["evaluations"])
            all_i += ei
            all_r += er
            all_t += tt
            print(f"{name:38s} {app_name:22s} {statistics.median(ei):13.3f} {statistics.median(er):13.3f} {statistics.median(tt):11.2f} {int(statistics.median(ev)):6d}")
    print(f"{'all':38s} {'':22s} {statistics.median(all_i):13.3f} {statistics.median(all_r):13.3f} {statistics.median(all_t):11.2f}")


if __name__ == "__main__":
    main()
