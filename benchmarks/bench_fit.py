"""Timing and precision of the "paper" and "fit" methods and of the fit of the ends' pixels (run on demand, not a test).

    python benchmarks/bench_fit.py [--runs N] [--noise DN] [--repeat K] [--recipe FILE]

On the same rendered images — an untextured, unshaded tennis ball
(R = 33.5 mm, z = 3 m, f = 3000 px, 50 kHz, 30 m/s; perpendicular and
30 degrees oblique in depth) plus Gaussian pixel noise of known sigma — it
runs detection once per image and the three refinements on it (``paper``;
``fit``, the default; ``pixels``, the fit with ``pixels=True``: the ball's
ends fitted pixel by pixel), and prints per
method and geometry: the median time per ball of detection, edges and the
refinement (``BallEstimate.extra``: ``time_edges_s``, ``time_shading_s``
(the fit's shading-aware second pass: shading model and edges measured
again), ``time_fit_s``, ``time_refine_s``) and of edges plus refinement
(``e+r``, the shading pass included: what a ball costs
after detection), the median over the balls of each fit's least time over
``--repeat`` runs of the same estimate (``least``: the fit's cost without
the interruptions of a shared machine, whose single timings move by tens
of per cent), the speed's bias and RMSE over the runs, the RMSE of ``vz`` against its
bound, the 1-sigma coverage of the reported speed sigma, and the speed
RMSE's ratio to the
Cramér–Rao bound of the pixel intensities (:func:`ballscan.solve.precision.pixel_crlb`:
the same pixel noise and contrast, not the fit's residuals).  One core.
"""

from __future__ import annotations

import os

# One core: set before numpy is imported so its thread pools start with one thread.
for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS", "NUMEXPR_NUM_THREADS"):
    os.environ[_var] = "1"

import argparse  # noqa: E402
import math  # noqa: E402
import statistics  # noqa: E402
import time  # noqa: E402
from dataclasses import replace  # noqa: E402
from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402

from ballscan.geometry.camera import LineScanCamera, line_times  # noqa: E402
from ballscan.measure.detection import detect  # noqa: E402
from ballscan.pipeline.estimate import estimate_region  # noqa: E402
from ballscan.errors import RecipeFileError  # noqa: E402
from ballscan.pipeline.recipe import Recipe, load_recipe  # noqa: E402
from ballscan.measure.images import LineImage  # noqa: E402
from ballscan.geometry.motion import BallMotion  # noqa: E402
from ballscan.solve.precision import pixel_crlb  # noqa: E402
from ballscan.model.render import Appearance, RenderSettings, render  # noqa: E402

CAMERA = LineScanCamera(2048, 3000.0, 1023.5, 50000.0, None)
RADIUS_M = 0.0335
N_LINES = 200
BACKGROUND = 0.1  # linear grey
BALL = 0.8  # linear grey (flat)
WHITE_DN = 1000.0  # DN per unit of linear grey; contrast = 700 DN
# The truth must be the continuous exposure: the default 4 x 8 (height x
# time) samples of an edge pixel leave 0.004 px RMS on the ball's lines and
# the default 16 x 16 on its first and last lines up to 0.01 px (4 x 8
# there: 0.066 px, three times the area's pixel noise here); 16 x 64 on
# every line, cap lines included, is within 0.004 px of a 32 x 256 render.
TRUTH_SAMPLING = RenderSettings(samples_across=16, samples_time=64, cap_across=16, cap_time=64)


def methods(base: Recipe = Recipe()) -> dict[str, Recipe]:
    """Label -> estimate_region's recipe: the paper's method, the fit of ``base`` (by default: edges and levelled end areas) and its fit of the ends' pixels."""
    return {"paper": replace(base, method="paper"), "fit": replace(base, method="fit", pixels=False), "pixels": replace(base, method="fit", pixels=True)}


METHODS = methods()


def geometries() -> list[tuple[str, BallMotion]]:
    """The benchmark's motions (camera frame; m, s, m/s)."""
    out = []
    for name, deg in (("perpendicular", 0.0), ("oblique 30 deg", 30.0)):
        a = math.radians(deg)
        out.append((name, BallMotion(RADIUS_M, 0.002, (0.0, 0.01, 3.0), (30.0 * math.cos(a), 0.0, 30.0 * math.sin(a)))))
    return out


def run(runs: int, noise_dn: float, repeat: int = 3, recipes: dict[str, Recipe] = METHODS) -> list[dict]:
    """Estimate every geometry ``runs`` times with every method of ``recipes``; one row per (geometry, method)."""
    rows = []
    t_lines = line_times(CAMERA, N_LINES)
    for gname, m in geometries():
        clean = render(CAMERA, (m, Appearance.flat(BALL)), N_LINES, background_level=BACKGROUND, noise=None, settings=TRUTH_SAMPLING).clean
        contrast = (BALL - BACKGROUND) * WHITE_DN
        bound = pixel_crlb(CAMERA, m, noise_dn, contrast)
        acc: dict[str, dict[str, list[float]]] = {k: {"det": [], "edges": [], "shade": [], "refine": [], "least": [], "err": [], "z": [], "vz": []} for k in recipes}
        rng = np.random.default_rng(12345)
        for _ in range(runs):
            data = clean * WHITE_DN + noise_dn * rng.standard_normal(clean.shape)
            img = LineImage(data, 1e12, 16, "bench")
            t0 = time.perf_counter()
            det = detect(img)
            t_det = time.perf_counter() - t0
            if len(det.regions) != 1:
                raise RuntimeError(f"{gname}: {len(det.regions)} balls detected")
            for method, recipe in recipes.items():
                b = estimate_region(img, det, det.regions[0], CAMERA, RADIUS_M, t_lines, recipe)
                a = acc[method]
                a["det"].append(t_det)
                if method != "paper":
                    a["edges"].append(b.extra["time_edges_s"])
                    a["shade"].append(b.extra["time_shading_s"])
                    a["refine"].append(b.extra["time_fit_s"])
                    # the least of `repeat` runs of the same estimate: the fit's
                    # cost without this shared machine's interruptions
                    again = [estimate_region(img, det, det.regions[0], CAMERA, RADIUS_M, t_lines, recipe) for _ in range(repeat - 1)]
                    a["least"].append(min([b.extra["time_fit_s"]] + [x.extra["time_fit_s"] for x in again]))
                else:
                    a["edges"].append(0.0)
                    a["shade"].append(0.0)
                    a["refine"].append(b.extra["time_refine_s"])
                    a["least"].append(math.nan)
                err = (b.speed_mps - m.speed_mps) if b.speed_mps is not None else math.nan
                a["err"].append(err)
                a["vz"].append(b.velocity_mps[2] - m.velocity_mps[2] if b.velocity_mps is not None else math.nan)
                if b.speed_sigma_mps:
                    a["z"].append(abs(err) <= b.speed_sigma_mps)
        for method, a in acc.items():
            err = np.asarray(a["err"])
            rmse = float(np.sqrt(np.nanmean(err**2)))
            rows.append(
                dict(
                    geometry=gname,
                    method=method,
                    det_ms=1000 * statistics.median(a["det"]),
                    edges_ms=1000 * statistics.median(a["edges"]),
                    shade_ms=1000 * statistics.median(a["shade"]),
                    refine_ms=1000 * statistics.median(a["refine"]),
                    least_ms=1000 * float(np.median(a["least"])),
                    total_ms=1000 * statistics.median([e + s + r for e, s, r in zip(a["edges"], a["shade"], a["refine"])]),
                    bias=float(np.nanmean(err)),
                    rmse=rmse,
                    crlb=bound.speed_sigma_mps,
                    ratio=rmse / bound.speed_sigma_mps,
                    cover=float(np.mean(a["z"])) if a["z"] else math.nan,
                    vz_rmse=float(np.sqrt(np.nanmean(np.asarray(a["vz"]) ** 2))),
                    vz_crlb=float(bound.velocity_sigma_mps[2]),
                )
            )
    return rows


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--runs", type=int, default=30, help="noisy images per geometry")
    ap.add_argument("--noise", type=float, default=5.0, help="Gaussian pixel noise, DN (contrast 700 DN)")
    ap.add_argument("--repeat", type=int, default=3, help="runs of each fit for the 'least' column (the fit's cost without the machine's interruptions)")
    ap.add_argument("--recipe", type=Path, help="a recipe file (TOML) whose changes all three methods take, e.g. a physics stage switched off")
    a = ap.parse_args()
    try:
        recipes = methods(load_recipe(a.recipe)) if a.recipe else METHODS
    except RecipeFileError as exc:
        raise SystemExit(f"error: {exc}") from None
    rows = run(a.runs, a.noise, max(a.repeat, 1), recipes)
    print(f"{a.runs} images per geometry, pixel noise {a.noise:g} DN, contrast {(BALL - BACKGROUND) * WHITE_DN:g} DN, one core")
    hdr = f"{'geometry':<15} {'method':<6} {'detect ms':>9} {'edges ms':>9} {'shade ms':>8} {'refine ms':>9} {'least ms':>8} {'e+r ms':>7} {'bias m/s':>10} {'RMSE m/s':>10} {'CRLB m/s':>10} {'RMSE/CRLB':>9} {'1-sig cov':>9} {'vz RMSE':>8} {'vz CRLB':>8}"
    print(hdr)
    print("-" * len(hdr))
    for r in rows:
        print(
            f"{r['geometry']:<15} {r['method']:<6} {r['det_ms']:9.1f} {r['edges_ms']:9.1f} {r['shade_ms']:8.1f} {r['refine_ms']:9.1f} {r['least_ms']:8.1f} {r['total_ms']:7.1f} "
            f"{r['bias']:+10.4f} {r['rmse']:10.4f} {r['crlb']:10.4f} {r['ratio']:9.2f} {r['cover']:9.2f} {r['vz_rmse']:8.3f} {r['vz_crlb']:8.3f}"
        )


if __name__ == "__main__":
    main()
