"""Two cameras against one: the joint estimate of a rig on seeded renders (run on demand, not a test).

    python benchmarks/bench_rig.py [--renders 100] [--angles 90,30] [--out FILE.pkl] [--figure docs/figures/rig_ellipses.png]
    python benchmarks/bench_rig.py --replot FILE.pkl --figure docs/figures/rig_ellipses.png

For each angle, the lane rig of :func:`ballscan.lab.rig.rig_for_angle`
(camera ``side`` 4 m beside the lane, camera ``second`` 4 m from it turned
``angle`` degrees about the flight direction; 2048 px, f = 4000 px,
70 kHz, gravity) renders ``--renders`` seeded balls (a flat tennis ball,
R = 33.5 mm, 30-50 m/s, azimuth and elevation within +-8 degrees, centre
within +-0.1 m of the lane's axis; the default sensor noise).  Each pair of
images is measured by :func:`ballscan.pipeline.rig.estimate_rig` (each
camera's own estimate, then the joint fit), and each camera's own estimate
is kept: the same balls, one camera against two.

Printed per angle:

* the direction error (angle between the estimated and the true world
  velocity, degrees): median and 95th percentile, joint and each camera alone;
* the largest principal sigma of the world velocity's covariance, the
  better single camera's over the joint's (median ratio);
* the RMS of error / joint Cramér–Rao sigma for speed, elevation and
  azimuth (:func:`ballscan.solve.rig_precision.rig_crlb` at the true motion
  with each camera's :func:`ballscan.solve.precision.sensor_crlb`: the
  renderer's sensor, any estimator on the pixels), beside each camera's own
  RMS error / its own bound on its well-measured axes (vx, vy): the
  estimator's efficiency on one camera;
* the RMS of error / reported sigma and the 1-sigma coverage of the reported
  sigmas (speed, elevation, azimuth, the three velocity components pooled);
* flags, and the wall time per ball (joint fit alone, and each camera's estimate).
"""

from __future__ import annotations

import os

for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS", "NUMEXPR_NUM_THREADS"):
    os.environ[_var] = "1"

import argparse  # noqa: E402
import math  # noqa: E402
import time  # noqa: E402

import numpy as np  # noqa: E402

from ballscan.geometry.rig import WorldMotion  # noqa: E402
from ballscan.lab.rig import rig_for_angle, simulate_rig  # noqa: E402
from ballscan.model.render import Appearance, SensorNoise  # noqa: E402
from ballscan.pipeline.rig import estimate_rig  # noqa: E402
from ballscan.solve.derived import launch_angles, world_covariance  # noqa: E402
from ballscan.solve.precision import sensor_crlb  # noqa: E402
from ballscan.solve.rig_precision import rig_crlb  # noqa: E402

RADIUS = 0.0335
BALL, BACKGROUND = 0.65, 0.1
N_LINES = 300


def ball(seed: int) -> WorldMotion:
    """Seeded ball: 30-50 m/s, azimuth and elevation within 8 degrees, centre within 0.1 m of the lane's axis at its crossing."""
    rng = np.random.default_rng(seed)
    speed = rng.uniform(30.0, 50.0)
    az, el = np.radians(rng.uniform(-8.0, 8.0, size=2))
    v = speed * np.array([math.cos(el) * math.cos(az), math.cos(el) * math.sin(az), math.sin(el)])
    p = np.array([0.0, *rng.uniform(-0.1, 0.1, size=2)])
    t = 0.5 * (N_LINES - 1) / 70000.0 + rng.uniform(-2e-4, 2e-4)
    return WorldMotion(RADIUS, t, tuple(p), tuple(v), (0.0, 0.0, -9.81))


def angle_between_deg(a, b) -> float:
    a, b = np.asarray(a, float), np.asarray(b, float)
    c = float(a @ b / (np.linalg.norm(a) * np.linalg.norm(b)))
    return math.degrees(math.acos(min(1.0, max(-1.0, c))))


def largest_sigma(C) -> float:
    return float(math.sqrt(max(np.linalg.eigvalsh(np.asarray(C, float)).max(), 0.0)))


def one(rig, seed: int, noise: SensorNoise = SensorNoise()) -> dict:
    truth = ball(seed)
    app = Appearance(ball_level=BALL, shading=False)
    sim = simulate_rig(rig, truth, N_LINES, app, seed=seed, noise=noise, background_level=BACKGROUND)
    t0 = time.perf_counter()
    rep = estimate_rig(sim.images, rig, RADIUS)
    wall = time.perf_counter() - t0
    out: dict = {"seed": seed, "n_balls": len(rep.balls), "wall_s": wall}
    if len(rep.balls) != 1 or rep.balls[0].motion is None:
        return out
    b = rep.balls[0]
    tr = truth.at(b.motion.t_ref_s)
    V, Vt = np.asarray(b.motion.velocity_mps), np.asarray(tr.velocity_mps)
    el, el_s, az, az_s = b.direction()
    el_t, _, az_t, _ = launch_angles(Vt, np.eye(3))
    sp, sp_s = b.speed()
    bound = rig_crlb(rig, tr, lambda cam, cm: sensor_crlb(cam, cm, noise, BALL, BACKGROUND).covariance)
    out.update(
        flags=list(b.flags), cameras=list(b.cameras), dir_err=angle_between_deg(V, Vt), v_err=V - Vt, v_sig=b.sigmas[4:7],
        cov_v=b.covariance[4:, 4:], joint_sigma=largest_sigma(b.covariance[4:, 4:]),
        speed=(sp - float(np.linalg.norm(Vt)), sp_s, bound.speed_sigma_mps),
        elev=(el - el_t, el_s, bound.elevation_sigma_deg),
        azim=(az - az_t, az_s, bound.azimuth_sigma_deg),
        fit_s=b.joint.run_time_s if b.joint else math.nan,
        own_s=sum(e.run_time_s for e in b.estimates.values()),
    )
    singles = []
    for rc in rig.cameras:
        e = b.estimates.get(rc.name)
        if e is None or e.velocity_mps is None or e.covariance is None:
            singles.append(None)
            continue
        Vw = rc.camera.vectors_to_world(np.asarray(e.velocity_mps))
        Cw = world_covariance(rc.camera, np.asarray(e.covariance))[4:, 4:]
        cm = sim.camera_motions[rig.cameras.index(rc)]
        cr = sensor_crlb(rc.camera, cm, noise, BALL, BACKGROUND)
        # the single camera's efficiency on its well-measured axes: vx and vy (its frame) over its own pixel bound
        ev = (np.asarray(e.velocity_mps) - np.asarray(cm.velocity_mps))[:2] / cr.velocity_sigma_mps[:2]
        singles.append({"dir_err": angle_between_deg(Vw, Vt), "sigma": largest_sigma(Cw), "v_err": Vw - Vt, "cov_v": Cw, "err_cr": ev})
    out["singles"] = singles
    return out


def summarise(angle: float, rows: list[dict]) -> list[str]:
    ok = [r for r in rows if "dir_err" in r]
    lines = [f"### Second camera at {angle:g} degrees: {len(ok)} of {len(rows)} renders measured by both cameras"]
    if not ok:
        return lines
    d = np.array([r["dir_err"] for r in ok])
    lines.append("")
    lines.append("| | direction error median [deg] | 95th pct [deg] | largest principal sigma of V, median [m/s] |")
    lines.append("|---|---|---|---|")
    singles_cr = []
    lines.append(f"| joint | {np.median(d):.4f} | {np.percentile(d, 95):.4f} | {np.median([r['joint_sigma'] for r in ok]):.4f} |")
    for k, name in enumerate(("side", "second")):
        s = [r["singles"][k] for r in ok if r["singles"][k] is not None]
        ds = np.array([x["dir_err"] for x in s])
        lines.append(f"| {name} alone | {np.median(ds):.3f} | {np.percentile(ds, 95):.3f} | {np.median([x['sigma'] for x in s]):.3f} |")
        singles_cr.append(np.array([x["err_cr"] for x in s]))
    ratio = [min(x["sigma"] for x in r["singles"] if x is not None) / r["joint_sigma"] for r in ok if any(x is not None for x in r["singles"])]
    lines.append("")
    lines.append(f"- largest principal sigma of the world velocity, better single camera / joint: median {np.median(ratio):.1f}x (min {np.min(ratio):.1f}x)")
    cov = []
    for key, label in (("speed", "speed"), ("elev", "elevation"), ("azim", "azimuth")):
        a = np.array([r[key] for r in ok])
        e, s, cr = a[:, 0], a[:, 1], a[:, 2]
        cov.append(np.abs(e) <= s)
        lines.append(
            f"- {label}: RMS error / joint CR sigma {math.sqrt(np.mean((e / cr) ** 2)):.2f}, RMS error / reported sigma "
            f"{math.sqrt(np.mean((e / s) ** 2)):.2f}, 1-sigma coverage {100 * np.mean(np.abs(e) <= s):.0f} %, mean reported / CR sigma {np.mean(s / cr):.2f}, "
            f"mean error / CR sigma {np.mean(e / cr):+.2f}"
        )
    e1 = np.concatenate(singles_cr)
    lines.append(f"- each camera alone, RMS error / its own pixel CR sigma (its frame): vx {math.sqrt(np.mean(e1[:, 0] ** 2)):.2f}, vy {math.sqrt(np.mean(e1[:, 1] ** 2)):.2f} (the estimator's efficiency on one camera)")
    ve = np.array([r["v_err"] for r in ok])
    vs = np.array([r["v_sig"] for r in ok])
    cov_v = np.abs(ve) <= vs
    lines.append(
        f"- velocity components: 1-sigma coverage {100 * np.mean(cov_v):.0f} % (VX {100 * np.mean(cov_v[:, 0]):.0f}, VY {100 * np.mean(cov_v[:, 1]):.0f}, "
        f"VZ {100 * np.mean(cov_v[:, 2]):.0f}); pooled with speed and angles {100 * np.mean(np.concatenate([np.concatenate(cov), cov_v.ravel()])):.0f} %"
    )
    flags = {}
    for r in rows:
        for f in r.get("flags", []):
            flags[f] = flags.get(f, 0) + 1
    lines.append(f"- flags: {flags or 'none'}; wall time per ball: joint fit median {1000 * np.median([r['fit_s'] for r in ok]):.1f} ms, "
                 f"the two cameras' own estimates {1000 * np.median([r['own_s'] for r in ok]):.0f} ms (ratio {np.median([r['fit_s'] / r['own_s'] for r in ok]):.2f})")
    return lines


def figure(rows: list[dict], path: str) -> None:
    """Velocity errors across the lane (VY, VZ) of one camera against two, with their median 1-sigma ellipses."""
    from matplotlib.figure import Figure
    from matplotlib.patches import Ellipse

    ok = [r for r in rows if "dir_err" in r and all(x is not None for x in r["singles"])]
    fig = Figure(figsize=(9.0, 4.2), layout="constrained")
    axes = fig.subplots(1, 2)
    colours = {"side alone": "#E69F00", "second alone": "#009E73", "joint": "#0072B2"}

    def ellipse(ax, C, colour):
        w, v = np.linalg.eigh(C)
        ang = math.degrees(math.atan2(v[1, 1], v[0, 1]))
        ax.add_patch(Ellipse((0, 0), 2 * math.sqrt(w[1]), 2 * math.sqrt(w[0]), angle=ang, fill=False, color=colour, lw=2.5, zorder=3))
        ax.add_patch(Ellipse((0, 0), 2 * math.sqrt(w[1]), 2 * math.sqrt(w[0]), angle=ang, fill=False, color="black", lw=0.8, ls="--", zorder=4))

    sets = [("side alone", [r["singles"][0] for r in ok]), ("second alone", [r["singles"][1] for r in ok]), ("joint", ok)]
    for ax, chosen, title in ((axes[0], sets, "one camera against two"), (axes[1], sets[2:], "two cameras (zoomed)")):
        for name, items in chosen:
            e = np.array([x["v_err"][1:] for x in items])
            ax.plot(e[:, 0], e[:, 1], ".", ms=3, color=colours[name], alpha=0.35, label=name)
            ellipse(ax, np.median([np.asarray(x["cov_v"])[1:, 1:] for x in items], axis=0), colours[name])
        ax.set_xlabel("error of V_Y (across the lane) [m/s]")
        ax.set_ylabel("error of V_Z (up) [m/s]")
        ax.set_title(title)
        ax.set_aspect("equal", adjustable="datalim")
        ax.grid(True, alpha=0.3)
    axes[0].legend(loc="upper right", fontsize=8)
    fig.suptitle("World velocity errors of seeded renders, with the median reported 1-sigma ellipse (second camera at 90 degrees)", fontsize=9)
    fig.savefig(path, dpi=110)


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--renders", type=int, default=100)
    ap.add_argument("--angles", default="90,30")
    ap.add_argument("--first", type=int, default=0)
    ap.add_argument("--prnu", type=float, default=SensorNoise().prnu_sigma, help="The sensors' column-gain scatter (PRNU), relative 1-sigma.")
    ap.add_argument("--figure", default=None)
    ap.add_argument("--out", default=None)
    ap.add_argument("--replot", default=None, help="Only redraw --figure from a saved --out file.")
    args = ap.parse_args(argv)
    if args.replot:
        import pickle

        with open(args.replot, "rb") as f:
            figure(pickle.load(f)[90.0], args.figure)
        return
    t0 = time.perf_counter()
    results = {}
    noise = SensorNoise(prnu_sigma=args.prnu)
    for a in (float(v) for v in args.angles.split(",")):
        rig = rig_for_angle(a)
        rows = [one(rig, seed, noise) for seed in range(args.first, args.first + args.renders)]
        results[a] = rows
        print("\n".join(summarise(a, rows)), flush=True)
        print(flush=True)
        if args.figure and a == 90.0:
            figure(rows, args.figure)
    print(f"total {time.perf_counter() - t0:.0f} s, load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores")
    if args.out:
        import pickle

        with open(args.out, "wb") as f:
            pickle.dump(results, f)


if __name__ == "__main__":
    main()
