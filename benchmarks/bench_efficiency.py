"""Efficiency of the fit against the Cramér–Rao bound on the quick Fig. 5 sweep's points (run on demand, not a test).

    python benchmarks/bench_efficiency.py [--points radius_m=0.11,line_rate_hz=140000]
        [--seeds 32] [--first 0] [--variants default,pixels,noprnu,truegain,fine] [--jobs 2]
        [--out FILE.npz] [--spread pixel_nodes=8,pixel_window_px=3.0]

Renders the trials of the quick sweep (:func:`ballscan.lab.experiments.fig5_quick_config`:
the test ``test_quick_fit_within_1p5_of_cramer_rao``'s sensor, ball and
seeds; trial ``k`` of a point is the test's trial ``k`` for ``k < 8``) and
measures each image with the estimator variants:

``default``
    ``estimate_image`` as the experiment calls it.
``pixels``
    The opt-in pixel fit (``pixels=True``).
``noprnu``
    The same scene rendered without PRNU (same seed; the noise draws
    differ since the gains are no longer drawn), the default estimator.
``truegain``
    The default estimator on the image with the true column gains divided
    out (``(DN - black) / g + black``): a flat-fielded sensor.
``fine``
    The scene rendered with 16 x 64 samples (tilt x time) of every edge
    pixel, cap lines included (the continuous exposure within 0.004 px), and
    the same noise draws (every pixel's shot noise is drawn as one normal
    deviate here: the paired difference to ``default`` is the renderer's
    sampling error's).

and prints, per point, variant and parameter (t_c, y0, z0, V.x, V.y, V.z,
speed), the RMSE over the trials divided by the bound's 1-sigma
(:func:`ballscan.solve.precision.sensor_crlb` at the point's nominal motion, as the
experiment), the mean error in bound sigmas (with its standard error), the
RMS of the errors in the estimate's own reported sigmas, and the median
``|relative speed error|`` over 0.6745 sigma (the test's ratio).  The trial
errors are saved with ``--out`` for paired comparisons between code versions.
"""

from __future__ import annotations

import os

for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS", "NUMEXPR_NUM_THREADS"):
    os.environ[_var] = "1"

import argparse  # noqa: E402
import math  # noqa: E402
import time  # noqa: E402
from dataclasses import replace  # noqa: E402

import numpy as np  # noqa: E402

PARAMS = ("t_c", "y0", "z0", "vx", "vy", "vz", "speed")
VARIANTS = ("default", "pixels", "noprnu", "truegain", "fine")
# the renderer's sampling of the continuous exposure (bench_fit.py's truth)
FINE = dict(samples_across=16, samples_time=64, cap_across=16, cap_time=64)


def _spec(factor: str, value: float, trial: int):
    from ballscan.lab import experiments as ex

    cfg = ex.fig5_quick_config()
    scene = cfg.scene.with_factor(factor, value)
    return ex.TrialSpec(cfg.name, factor, float(value), "none", trial, scene, cfg.methods, ex.trial_seed(cfg.seed, factor, value, "none", trial))


def _vector(b, truth) -> tuple[np.ndarray, np.ndarray, dict]:
    """Errors and reported sigmas of (t_c, y0, z0, vx, vy, vz, speed)."""
    nan7 = np.full(7, np.nan)
    if b is None or b.velocity_mps is None or b.t_c_s is None or b.position_m is None:
        return nan7, nan7, {}
    est = np.r_[b.t_c_s, b.position_m[1], b.position_m[2], b.velocity_mps, b.speed_mps]
    tru = np.r_[truth.t_c_s, truth.position_m[1], truth.position_m[2], truth.velocity_mps, truth.speed_mps]
    sig = np.r_[b.t_c_sigma_s, b.position_sigma_m[1], b.position_sigma_m[2], b.velocity_sigma_mps, b.speed_sigma_mps]
    info = {k: b.extra.get(k) for k in ("edges", "pixels", "flat_fielded", "shading_pass", "partial_levelled", "n_edges")}
    return est - tru, sig, info


def trial_scene(factor: str, value: float, trial: int):
    """The experiment's trial ``trial`` at ``factor = value``: its spec, seed state, geometry and untextured appearance (as the experiment renders it)."""
    from ballscan.lab import experiments as ex

    spec = _spec(factor, value, trial)
    state = np.random.SeedSequence(spec.seed).generate_state(3, dtype=np.uint32)
    phase = float(state[1]) / 2.0**32 - 0.5
    return spec, state, ex.scene_geometry(spec.scene, phase), ex.appearance(spec.scene, "none", int(state[2]))


def run_one(args: tuple[str, float, int, tuple[str, ...]]) -> dict:
    """Render trial ``trial`` of a point and measure it with each variant."""
    from ballscan.lab import experiments as ex
    from ballscan.pipeline.estimate import estimate_image
    from ballscan.measure.images import LineImage
    from ballscan.model.render import render

    from ballscan.pipeline.recipe import Recipe

    factor, value, trial, variants, spread = args
    # an experiment: the spread-pixel fit's settings changed (Recipe.spread_fit)
    recipe = Recipe(spread_fit=replace(Recipe().spread_fit, **spread))
    spec, state, geom, app = trial_scene(factor, value, trial)
    truth = geom.motion
    cam = spec.scene.camera
    R = spec.scene.radius_m
    out = {"trial": trial}
    rendered = render(cam, (truth, app), geom.n_lines, background_level=spec.scene.background_level, noise=spec.scene.noise, seed=int(state[0]))
    noise = spec.scene.noise

    def measure(name, data, pixels=False):
        t0 = time.perf_counter()
        img = LineImage(np.asarray(data, dtype=float), float(noise.max_dn), noise.bits, name)
        rep = estimate_image(img, cam, R, recipe=replace(recipe, pixels=pixels))
        b, _ = ex.pick_estimate(rep, truth.t_c_s)
        err, sig, info = _vector(b, truth)
        out[name] = {"err": err, "sig": sig, "info": info, "time": time.perf_counter() - t0}

    for v in variants:
        if v == "default":
            measure(v, rendered.image)
        elif v == "pixels":
            measure(v, rendered.image, pixels=True)
        elif v == "truegain":
            g = rendered.column_gain[None, :]
            measure(v, (rendered.image.astype(float) - noise.black_dn) / g + noise.black_dn)
        elif v == "noprnu":
            r0 = render(cam, (truth, app), geom.n_lines, background_level=spec.scene.background_level, noise=replace(noise, prnu_sigma=0.0), seed=int(state[0]))
            measure(v, r0.image)
        elif v == "fine":
            from ballscan.model.render import RenderSettings

            rf = render(cam, (truth, app), geom.n_lines, background_level=spec.scene.background_level, noise=noise, seed=int(state[0]), settings=RenderSettings(**FINE))
            measure(v, rf.image)
        else:
            raise ValueError(f"unknown variant {v!r}")
    return out


def bound_sigmas(factor: str, value: float, flat_field: bool = False) -> np.ndarray:
    """The bound's 1-sigma of (t_c, y0, z0, vx, vy, vz, speed) at the point's nominal motion."""
    from ballscan.lab import experiments as ex
    from ballscan.solve.precision import sensor_crlb

    sc = _spec(factor, value, 0).scene
    geom = ex.scene_geometry(sc, 0.0)
    b = sensor_crlb(sc.camera, geom.motion, sc.noise, sc.ball_level, sc.background_level, flat_field=flat_field)
    return np.r_[b.sigmas, b.speed_sigma_mps], geom.motion.speed_mps


def summarise(results: list[dict], crb: np.ndarray, speed: float, variants, label: str) -> None:
    print(f"\n== {label}: {len(results)} trials; bound sigmas " + " ".join(f"{p}={s:.3g}" for p, s in zip(PARAMS, crb)))
    print(f"{'variant':<9} {'param':<6} {'RMSE/crb':>9} {'mean/crb':>9} {'+-':>6} {'rms z':>7}")
    for v in variants:
        E = np.array([r[v]["err"] for r in results])
        S = np.array([r[v]["sig"] for r in results])
        ok = np.all(np.isfinite(E), axis=1)
        E, S = E[ok], S[ok]
        n = len(E)
        for k, p in enumerate(PARAMS):
            rmse = math.sqrt(np.mean(E[:, k] ** 2)) / crb[k]
            mean = np.mean(E[:, k]) / crb[k]
            se = np.std(E[:, k], ddof=1) / crb[k] / math.sqrt(n)
            z = math.sqrt(np.mean((E[:, k] / S[:, k]) ** 2))
            print(f"{v:<9} {p:<6} {rmse:9.3f} {mean:+9.3f} {se:6.3f} {z:7.3f}")
        med = np.median(np.abs(E[:, 6])) / speed / (0.6745 * crb[6] / speed)
        med8 = np.median(np.abs(E[:8, 6])) / (0.6745 * crb[6]) if n >= 8 else math.nan
        infos = {}
        for r in results:
            key = (r[v]["info"].get("edges"), r[v]["info"].get("pixels"), r[v]["info"].get("flat_fielded"))
            infos[key] = infos.get(key, 0) + 1
        t = np.median([r[v]["time"] for r in results])
        print(f"{v:<9} median|speed err|/(0.6745 crb): {med:.3f} (all {n}), {med8:.3f} (first 8); paths {infos}; {t:.2f} s/trial")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--points", default="radius_m=0.11,line_rate_hz=140000")
    ap.add_argument("--seeds", type=int, default=32)
    ap.add_argument("--first", type=int, default=0, help="first trial index")
    ap.add_argument("--variants", default="default,pixels,noprnu,truegain")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--out", default=None, help="save the trial errors (npz)")
    ap.add_argument("--spread", default="", help="experiment: FitSettings of the spread-pixel fit (Recipe.spread_fit) changed, e.g. 'pixel_nodes=16,pixel_window_px=6.0'")
    a = ap.parse_args()
    import ast

    from joblib import Parallel, delayed

    from ballscan.solve.settings import FitSettings

    variants = tuple(a.variants.split(","))
    spread = {}
    for item in filter(None, a.spread.split(",")):
        k, val = item.split("=")
        spread[k] = type(getattr(FitSettings(), k))(ast.literal_eval(val))
    pts = []
    for item in a.points.split(","):
        f, v = item.split("=")
        pts.append((f, float(v)))
    save = {}
    for f, v in pts:
        t0 = time.perf_counter()
        tasks = [(f, v, k, variants, spread) for k in range(a.first, a.first + a.seeds)]
        res = Parallel(n_jobs=a.jobs)(delayed(run_one)(t) for t in tasks)
        crb, speed = bound_sigmas(f, v)
        summarise(res, crb, speed, variants, f"{f}={v:g} ({time.perf_counter() - t0:.0f} s)")
        for var in variants:
            save[f"{f}={v:g}/{var}/err"] = np.array([r[var]["err"] for r in res])
            save[f"{f}={v:g}/{var}/sig"] = np.array([r[var]["sig"] for r in res])
        save[f"{f}={v:g}/crb"] = crb
    if a.out:
        np.savez(a.out, **save)


if __name__ == "__main__":
    main()
