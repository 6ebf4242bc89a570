"""Do the reported sigmas cover the errors as a normal distribution would?  (run on demand, not a test)

    python benchmarks/bench_coverage.py [--scenes 200] [--seed 0] [--jobs 2] [--out FILE.npz] [--recipe FILE.toml]

Draws ``--scenes`` scenes at random (seeded) over the experiments' ranges
(:class:`ballscan.lab.experiments.Scene`, the fig5 camera of 2048 px and
f = 4000 px): radius 0.02-0.11 m, speed 4.7-60 m/s, line rate
10 000-140 000 lines/s (log-uniform), direction -45..45 deg along the sensor
and -20..20 deg in depth, depth 2-6 m, centre -0.2..0.2 m along the sensor,
a bright ball on a dark background or the reverse, flat or Lambertian-shaded,
untextured or with the tennis seam; the default 8-bit sensor (read and shot
noise, 0.8 % PRNU).  Each is rendered once (the experiments' renderer, a
random sub-line phase), measured by ``estimate_image`` with the default
recipe (or ``--recipe``'s, :func:`ballscan.pipeline.recipe.load_recipe`),
and the errors of the speed (``speed_mps`` against ``speed_sigma_mps``), of
the two direction angles (``direction_deg`` against
``direction_sigma_deg``, :mod:`ballscan.solve.derived`) and of ``|V.x|``
(the speed along the lane, against its sigma in ``velocity_sigma_mps``) are
divided by their sigmas.  It prints the share of balls within 1 and 3
sigmas (a normal distribution: 68.3 % and 99.7 %) over all balls and by
texture, by the share of the depth velocity and by the ball's length in
lines, and the RMS of the z-scores.
"""

from __future__ import annotations

import os

for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS", "NUMEXPR_NUM_THREADS"):
    os.environ[_var] = "1"

import argparse  # noqa: E402
import math  # noqa: E402
import time  # noqa: E402

import numpy as np  # noqa: E402
from joblib import Parallel, delayed  # noqa: E402

QUANTITIES = ("speed", "psi_y", "psi_z", "|vx|")


def draw_scene(rng: np.random.Generator):
    """One random scene (a :class:`~ballscan.lab.experiments.Scene` valid for an experiment) and its texture."""
    from dataclasses import replace

    from ballscan.lab import experiments as ex

    base = ex.fig5_config().scene
    while True:
        bright = rng.random() < 0.5
        levels = (0.7, 0.1) if bright else (0.15, 0.75)
        scene = replace(
            base,
            camera=replace(base.camera, line_rate_hz=float(np.exp(rng.uniform(math.log(1e4), math.log(1.4e5))))),
            radius_m=float(np.exp(rng.uniform(math.log(0.02), math.log(0.11)))),
            speed_mps=float(np.exp(rng.uniform(math.log(4.7), math.log(60.0)))),
            direction_deg=float(rng.uniform(-45.0, 45.0)),
            direction_z_deg=float(rng.uniform(-20.0, 20.0)),
            z_m=float(rng.uniform(2.0, 6.0)),
            y_m=float(rng.uniform(-0.2, 0.2)),
            ball_level=levels[0],
            background_level=levels[1],
            shading=bool(rng.random() < 0.5),
        )
        texture = "tennis" if rng.random() < 0.5 else "none"
        try:
            ex.ExperimentConfig(name="coverage", scene=scene, sweeps=(ex.Sweep("z_m", (scene.z_m,)),), trials=1, textures=(texture,), methods=("fit",), bound=False)
        except ex.ExperimentConfigError:
            continue  # outside the sensor or too many lines: draw again
        return scene, texture


def run_one(k: int, seed: int, recipe=None) -> dict:
    """Render and measure scene ``k``; the z-scores of speed and direction angles."""
    from ballscan.lab import experiments as ex
    from ballscan.measure.images import LineImage
    from ballscan.model.render import render
    from ballscan.model.silhouette import visible_line_count
    from ballscan.pipeline.estimate import estimate_image
    from ballscan.pipeline.recipe import Recipe

    rng = np.random.default_rng([seed, k])
    scene, texture = draw_scene(rng)
    geom = ex.scene_geometry(scene, float(rng.uniform(-0.5, 0.5)))
    truth = geom.motion
    r = render(scene.camera, (truth, ex.appearance(scene, texture, int(rng.integers(2**31)))), geom.n_lines,
               background_level=scene.background_level, noise=scene.noise, seed=int(rng.integers(2**31)))
    image = LineImage(r.image.astype(float), float(scene.noise.max_dn), scene.noise.bits, f"scene {k}")
    rep = estimate_image(image, scene.camera, scene.radius_m, recipe=recipe or Recipe())
    ball, _ = ex.pick_estimate(rep, truth.t_c_s)
    V = np.asarray(truth.velocity_mps)
    out = dict(k=k, texture=texture, shading=scene.shading, lines=float(visible_line_count(scene.camera, truth)), vz_share=abs(V[2]) / np.linalg.norm(V),
               z=np.full(len(QUANTITIES), np.nan), flags="no_detection" if ball is None else ";".join(ball.flags))
    der = ball.derived(scene.camera) if ball is not None else None
    if der is None or ball.speed_mps is None or ball.speed_sigma_mps is None:
        return out
    true_dir = np.degrees([math.atan2(V[1], V[0]), math.atan2(V[2], V[0])])
    est = np.r_[ball.speed_mps, der.direction_deg, abs(ball.velocity_mps[0])]
    sig = np.r_[ball.speed_sigma_mps, der.direction_sigma_deg, ball.velocity_sigma_mps[0]]
    out["z"] = (est - np.r_[truth.speed_mps, true_dir, abs(V[0])]) / sig
    out["rel_speed_error"] = (ball.speed_mps - truth.speed_mps) / truth.speed_mps
    return out


def table(results: list[dict], label: str) -> str:
    z = np.array([r["z"] for r in results])
    ok = np.all(np.isfinite(z), axis=1)
    z = z[ok]
    cells = [f"{label:<28} {ok.sum():>4}"]
    for q in range(len(QUANTITIES)):
        a = np.abs(z[:, q])
        cells.append(f"{100 * np.mean(a < 1):6.1f} {100 * np.mean(a < 3):6.1f} {np.sqrt(np.mean(a**2)):6.2f}")
    return "  ".join(cells)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--scenes", type=int, default=200)
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--out", default=None)
    ap.add_argument("--recipe", default=None, help="a recipe file (docs/geometry.md) in place of the default recipe")
    a = ap.parse_args()
    recipe = None
    if a.recipe:
        from ballscan.pipeline.recipe import load_recipe

        recipe = load_recipe(a.recipe)
    t0 = time.perf_counter()
    res = Parallel(n_jobs=a.jobs)(delayed(run_one)(k, a.seed, recipe) for k in range(a.scenes))
    wall = time.perf_counter() - t0
    print(f"{a.scenes} scenes, seed {a.seed}, {wall:.0f} s wall on {a.jobs} jobs; "
          f"{sum(not np.all(np.isfinite(r['z'])) for r in res)} without a speed and direction sigma")
    print(f"{'':<28} {'n':>4}  " + "  ".join(f"{q + ' 1s %':>6} {'3s %':>6} {'RMS z':>6}" for q in QUANTITIES))
    groups = [("all", res)]
    groups += [(f"texture {t}", [r for r in res if r["texture"] == t]) for t in ("none", "tennis")]
    groups += [(f"shading {'on' if s else 'off'}", [r for r in res if r["shading"] == s]) for s in (False, True)]
    groups += [("|V.z| <= 0.1 |V|", [r for r in res if r["vz_share"] <= 0.1]), ("|V.z| > 0.1 |V|", [r for r in res if r["vz_share"] > 0.1])]
    groups += [("< 150 lines seen", [r for r in res if r["lines"] < 150]), (">= 150 lines seen", [r for r in res if r["lines"] >= 150])]
    for label, g in groups:
        if g:
            print(table(g, label))
    if a.out:
        np.savez(a.out, z=np.array([r["z"] for r in res]), texture=np.array([r["texture"] for r in res]),
                 shading=np.array([r["shading"] for r in res]), vz_share=np.array([r["vz_share"] for r in res]),
                 lines=np.array([r["lines"] for r in res]), flags=np.array([r["flags"] for r in res]))


if __name__ == "__main__":
    main()
