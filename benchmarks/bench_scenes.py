"""Accuracy on the independent ray-traced reference scenes, re-noised (run on demand).

    python benchmarks/bench_scenes.py [--seeds N] [--scenes DIR] [--paper]

The reference scenes (POV-Ray renders of textured, shaded balls with exact
truth, ``../shared/scenes`` or ``tests/data/scenes``) come with one noisy
8-bit image each, so one image says little about an estimator whose error is
a random variable.  Their noise-free 16-bit renders (``clean/NAME.png``,
linear grey x 65535) and their documented sensor model (``noise`` in
``NAME.truth.json``:
``DN = black + Poisson(Y g_j full_well) white / full_well + N(0, read^2)``,
rounded and clipped to 8 bits, ``g_j`` a per-column gain) give as many
independent noisy images of the same scenes as wanted.  Each is estimated
with the fit with and without its shading-aware second pass (and the
paper's method with ``--paper``), and the script prints per scene and ball
and over all balls: the median, mean and largest relative speed error, its
bias, the RMS of the V.z error beside the median reported V.z sigma, the
fraction of speed errors within 1 and 3 reported sigma, and the median time
per ball.  One core.
"""

from __future__ import annotations

import os

for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS", "NUMEXPR_NUM_THREADS"):
    os.environ[_var] = "1"

import argparse  # noqa: E402
import json  # noqa: E402
import statistics  # noqa: E402
from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402

from ballscan.geometry.camera import load_camera  # noqa: E402
from ballscan.pipeline.estimate import estimate_image  # noqa: E402
from ballscan.pipeline.recipe import Recipe  # noqa: E402
from ballscan.measure.images import LineImage, load_image  # noqa: E402

HERE = Path(__file__).resolve().parent
DEFAULT_DIRS = (HERE.parent.parent / "shared" / "scenes", HERE.parent / "tests" / "data" / "scenes")
VARIANTS = {"fit": Recipe(), "fit, 1 pass": Recipe(shading=False), "paper": Recipe(method="paper")}


def renoise(clean_y: np.ndarray, noise: dict, seed: int) -> np.ndarray:
    """An 8-bit image of linear grey ``clean_y`` under the scenes' sensor model (``noise`` of the truth file)."""
    rng = np.random.default_rng(seed)
    gain = 1.0 + noise["prnu_sigma"] * rng.standard_normal(clean_y.shape[1])
    electrons = rng.poisson(np.maximum(clean_y * gain * noise["full_well_e"], 0.0))
    dn = noise["black_dn"] + electrons * noise["white_dn"] / noise["full_well_e"] + rng.normal(0.0, noise["read_dn"], clean_y.shape)
    return np.clip(np.rint(dn), 0, 255)


def run(scene_dir: Path, seeds: int, variants: list[str]) -> list[dict]:
    """One row per (scene, ball, seed, variant)."""
    rows = []
    for truth_path in sorted(scene_dir.glob("*.truth.json")):
        name = truth_path.name[: -len(".truth.json")]
        clean_path = scene_dir / "clean" / f"{name}.png"
        if not clean_path.exists():
            continue
        truth = json.loads(truth_path.read_text())
        balls = truth.get("balls", [truth])
        camera = load_camera(scene_dir / f"{name}.camera.toml")
        clean_y = load_image(clean_path).data / 65535.0
        for seed in range(seeds):
            image = LineImage(renoise(clean_y, truth["noise"], 1000 + seed), 255.0, 8, f"{name}#{seed}")
            for variant in variants:
                est = estimate_image(image, camera, balls[0]["radius_m"], recipe=VARIANTS[variant]).balls
                # one estimate per true ball: the nearest t_c within 5 line
                # periods, each estimate used once
                free = [b for b in est if b.t_c_s is not None]
                for index, tb in enumerate(balls):
                    speed = float(np.linalg.norm(tb["velocity_mps"]))
                    near = [b for b in free if abs(b.t_c_s - tb["t_c_s"]) < 5.0 / camera.line_rate_hz]
                    if not near:
                        rows.append(dict(scene=name, ball=index, seed=seed, variant=variant, found=False, undetermined=False))
                        continue
                    b = min(near, key=lambda b: abs(b.t_c_s - tb["t_c_s"]))
                    free.remove(b)
                    if b.speed_mps is None:
                        rows.append(dict(scene=name, ball=index, seed=seed, variant=variant, found=False, undetermined=True))
                        continue
                    sigma = b.speed_sigma_mps if b.speed_sigma_mps is not None else float("nan")
                    vz_sigma = b.velocity_sigma_mps[2] if b.velocity_sigma_mps is not None else float("nan")
                    rows.append(
                        dict(
                            scene=name, ball=index, seed=seed, variant=variant, found=True,
                            err=(b.speed_mps - speed) / speed, z=abs(b.speed_mps - speed) / sigma if sigma > 0 else float("nan"),
                            vz_err=b.velocity_mps[2] - tb["velocity_mps"][2], vz_sigma=vz_sigma, time_s=b.run_time_s,
                        )
                    )
    return rows


def summary(rows: list[dict]) -> str:
    """Fixed-width table of the rows, per scene/ball and overall, for each variant."""
    head = f"{'scene':24s} {'ball':>4s} {'method':12s} {'n':>3s} {'med|e| %':>9s} {'mean|e| %':>9s} {'max|e| %':>9s} {'bias %':>8s} {'vz RMS':>7s} {'vz sig':>7s} {'in 1sig':>7s} {'in 3sig':>7s} {'ms/ball':>8s}"
    out = [head]
    keys = sorted({(r["scene"], r["ball"]) for r in rows}) + [("all", -1)]
    variants = list(dict.fromkeys(r["variant"] for r in rows))
    for scene, ball in keys:
        for v in variants:
            sel = [r for r in rows if r["variant"] == v and r["found"] and (scene == "all" or (r["scene"], r["ball"]) == (scene, ball))]
            if not sel:
                continue
            e = np.array([abs(r["err"]) for r in sel]) * 100
            bias = float(np.mean([r["err"] for r in sel])) * 100
            z = np.array([r["z"] for r in sel], dtype=float)
            vz = np.array([r["vz_err"] for r in sel])
            vz_sig = np.array([r["vz_sigma"] for r in sel], dtype=float)
            ms = statistics.median(r["time_s"] for r in sel) * 1000
            within = (lambda k: f"{np.mean(z[np.isfinite(z)] < k):7.2f}" if np.isfinite(z).any() else f"{'-':>7s}")
            sig_txt = f"{np.nanmedian(vz_sig):7.2f}" if np.isfinite(vz_sig).any() else f"{'-':>7s}"
            label = scene.removeprefix("pub_") if scene != "all" else "all balls"
            out.append(
                f"{label:24s} {ball if ball >= 0 else '':>4} {v:12s} {len(sel):3d} {np.median(e):9.3f} {e.mean():9.3f} {e.max():9.2f} {bias:+8.3f} "
                f"{np.sqrt(np.mean(vz**2)):7.2f} {sig_txt} {within(1)} {within(3)} {ms:8.1f}"
            )
    missing = sum(not r["found"] and not r.get("undetermined") for r in rows)
    undetermined = sum(bool(r.get("undetermined")) for r in rows)
    out.append(f"balls not found: {missing}; found with the speed undetermined: {undetermined}")
    return "\n".join(out)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--seeds", type=int, default=10, help="noise realisations per scene")
    ap.add_argument("--scenes", type=Path, default=None, help="scene folder (default: ../shared/scenes, else tests/data/scenes)")
    ap.add_argument("--paper", action="store_true", help="also run the paper's method (about 0.6 s per ball)")
    args = ap.parse_args()
    scene_dir = args.scenes or next((d for d in DEFAULT_DIRS if d.is_dir()), None)
    if scene_dir is None or not scene_dir.is_dir():
        raise SystemExit(f"bench_scenes: no scene folder (tried {', '.join(map(str, DEFAULT_DIRS))})")
    variants = ["fit", "fit, 1 pass"] + (["paper"] if args.paper else [])
    rows = run(scene_dir, args.seeds, variants)
    print(f"{scene_dir} re-noised with the scenes' own sensor model, {args.seeds} seeds, one core")
    print(summary(rows))


if __name__ == "__main__":
    main()
