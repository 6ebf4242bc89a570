"""Are the reported 1-sigma honest?  z-scores of the precise fit against the truth (run on demand, not a test).

    python benchmarks/bench_calibration.py [--balls N] [--jobs J] [--cases NAME,...]
        [--start {guess,loose_fit}] [--level-samples T,H] [--refined-background] [--refit-law] [--clean]
        [--stream {engine,crop}]

For each case (a camera, a ball length in lines, flat or Lambertian-shaded
ball) it renders ``--balls`` single images of one ball on the default
8-bit sensor (read and shot noise, 0.8 % PRNU) with random lateral
position, sub-line phase and velocity components along the sensor and in
depth, at the renderer's finest sampling (16 x 64 per edge pixel on every
line: the truth of a continuous exposure), runs ``estimate_image`` and
prints, per estimated quantity, the RMS and the mean of
``z = (estimate - truth) / sigma``.  An honest sigma gives RMS z = 1 and a
mean within ``1 / sqrt(N)`` of 0; RMS z = 2 means the reported sigma is half
the actual error.  Also the edges used (``extra["edges"]``).

``--start``, ``--level-samples``, ``--refined-background`` and ``--refit-law`` set the
shading pass's options of the estimator's :class:`ballscan.pipeline.recipe.Recipe`.
``--clean`` also renders each ball noise-free (16 bits, no PRNU) and prints
its errors in units of the noisy image's sigmas: the estimator's own
(model) error, which no noise averages away.

``--stream`` measures the balls as ``ballscan watch`` does instead: each
ball in a 1024-line chunk of its own between background chunks, one
stream per worker, through :func:`ballscan.stream.engine.process_stream` with
``StreamConfig(background=...)`` (the engine's running background of the
crop's columns, or the crop's own); ``--clean`` and the shading options
do not apply there.

Cases: ``stream-38`` / ``stream-112`` / ``stream-268`` are the stream
tests' camera (512 px, f = 1100 px, 20 kHz, z = 4 m: an 18-px-wide tennis
ball) at 35 / 12 / 5 m/s; ``wide-117`` the stream benchmark's (2048 px,
f = 4000 px, 70 kHz, z = 4 m, 40 m/s: 67 px wide, 117 lines, 109 with both edges).  Each with
``-flat`` or ``-shaded``.
"""

from __future__ import annotations

import os

for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS", "NUMEXPR_NUM_THREADS"):
    os.environ[_var] = "1"

import argparse  # noqa: E402
from collections import Counter  # noqa: E402
from dataclasses import dataclass, replace  # noqa: E402

import numpy as np  # noqa: E402
from joblib import Parallel, delayed  # noqa: E402

from ballscan.geometry.camera import LineScanCamera  # noqa: E402
from ballscan.pipeline.estimate import estimate_image  # noqa: E402
from ballscan.pipeline.recipe import Recipe  # noqa: E402
from ballscan.measure.images import LineImage  # noqa: E402
from ballscan.geometry.motion import BallMotion  # noqa: E402
from ballscan.model.render import Appearance, RenderSettings, SensorNoise, apply_sensor, render  # noqa: E402
from ballscan.stream.engine import StreamConfig, process_stream  # noqa: E402

RADIUS_M = 0.0335
FINE = RenderSettings(samples_across=16, samples_time=64, cap_across=16, cap_time=64)
NAMES = ("t_c", "y0", "z0", "vx", "vy", "vz")


@dataclass(frozen=True)
class Case:
    name: str
    camera: LineScanCamera
    speed_mps: float
    z_m: float
    shaded: bool

    @property
    def lines(self) -> float:
        return 2 * RADIUS_M / self.speed_mps * self.camera.line_rate_hz


STREAM_CAM = LineScanCamera(width=512, focal_px=1100.0, principal_px=255.5, line_rate_hz=20000.0)
WIDE_CAM = LineScanCamera(width=2048, focal_px=4000.0, principal_px=1023.5, line_rate_hz=70000.0)
CASES = {
    f"{base}-{look}": Case(f"{base}-{look}", cam, v, 4.0, look == "shaded")
    for base, cam, v in (("stream-38", STREAM_CAM, 35.0), ("stream-112", STREAM_CAM, 12.0), ("stream-268", STREAM_CAM, 5.0), ("wide-117", WIDE_CAM, 40.0))
    for look in ("flat", "shaded")
}


def _random_motion(case: Case, rng: np.random.Generator, t_c_s: float) -> BallMotion:
    """A ball of ``case`` crossing at ``t_c_s``: lateral position within the middle half of the field, velocity 6 % of the speed along y and 9 % in depth."""
    cam = case.camera
    half_field = 0.25 * cam.width / cam.focal_px * case.z_m
    v = case.speed_mps
    return BallMotion(
        RADIUS_M,
        t_c_s,
        (0.0, rng.uniform(-half_field, half_field), case.z_m),
        (v, rng.uniform(-0.06, 0.06) * v, rng.uniform(-0.09, 0.09) * v),
    )


def one_ball(case: Case, k: int, recipe: Recipe = Recipe(), clean: bool = False) -> tuple[np.ndarray, np.ndarray, str]:
    """z-scores of ball ``k`` of ``case``, of its noise-free twin (NaN unless ``clean``) and the edges it used."""
    rng = np.random.default_rng(1000 + k)
    cam = case.camera
    n_img = int(case.lines * 1.6) + 20
    m = _random_motion(case, rng, (n_img / 2 + rng.uniform(-0.5, 0.5)) / cam.line_rate_hz)
    app = Appearance(texture="none", shading=case.shaded, ball_level=0.8)
    true = np.r_[m.t_c_s, m.position_m[1:], m.velocity_mps]
    none = np.full(6, np.nan)

    def measured(image: LineImage):
        balls = estimate_image(image, cam, RADIUS_M, recipe=recipe).balls
        return balls[0] if len(balls) == 1 and balls[0].t_c_s is not None else None

    r = render(cam, [(m, app)], n_img, background_level=0.12, noise=SensorNoise(), seed=k, settings=FINE)
    e = measured(LineImage(r.image.astype(float), 255.0, 8, case.name))
    if e is None:
        return none, none, "none"
    sig = np.r_[e.t_c_sigma_s, e.position_sigma_m[1:], e.velocity_sigma_mps]
    z = (np.r_[e.t_c_s, e.position_m[1:], e.velocity_mps] - true) / sig
    z_clean = none
    if clean:
        rc = render(cam, [(m, app)], n_img, background_level=0.12, noise=None, seed=k, settings=FINE)
        ec = measured(LineImage(rc.image.astype(float), 65535.0, 16, case.name + " clean"))
        if ec is not None:
            z_clean = (np.r_[ec.t_c_s, ec.position_m[1:], ec.velocity_mps] - true) / sig
    return z, z_clean, str(e.extra.get("edges"))


STREAM_CHUNK = 1024


def stream_balls(case: Case, ks: list[int], background: str) -> list[tuple[np.ndarray, np.ndarray, str]]:
    """z-scores of balls ``ks`` of ``case`` measured in one stream (``--stream``): each in a chunk of its own after a background chunk."""
    cam = case.camera
    app = Appearance(texture="none", shading=case.shaded, ball_level=0.8)
    noise_rng = np.random.default_rng(ks[0])
    # the column gains (PRNU) are the sensor's fixed pattern: once per stream
    sensor = SensorNoise()
    gain = 1.0 + sensor.prnu_sigma * noise_rng.standard_normal(cam.width)
    noise = replace(sensor, prnu_sigma=0.0)
    truths: list[BallMotion] = []

    def chunks():
        for i, k in enumerate(ks):
            yield apply_sensor(np.full((STREAM_CHUNK, cam.width), 0.12 * gain), noise, noise_rng)[0]
            rng = np.random.default_rng(1000 + k)
            line = rng.uniform(300.0, STREAM_CHUNK - 300.0 - case.lines)
            m = _random_motion(case, rng, line / cam.line_rate_hz)
            r = render(cam, [(m, app)], STREAM_CHUNK, background_level=0.12, noise=None, settings=FINE)
            truths.append(BallMotion(RADIUS_M, ((2 * i + 1) * STREAM_CHUNK + line) / cam.line_rate_hz, m.position_m, m.velocity_mps))
            yield apply_sensor(r.clean * gain[None, :], noise, noise_rng)[0]
        yield apply_sensor(np.full((STREAM_CHUNK, cam.width), 0.12 * gain), noise, noise_rng)[0]

    none = np.full(6, np.nan)
    found = {}
    for res in process_stream(chunks(), cam, RADIUS_M, StreamConfig(background=background), source=case.name):
        e = res.estimate
        if e.t_c_s is None:
            continue
        i = int(e.t_c_s * cam.line_rate_hz) // (2 * STREAM_CHUNK)
        if i in found or i >= len(ks):
            found[i] = None  # two estimates of one ball: not measured
            continue
        m = truths[i]
        sig = np.r_[e.t_c_sigma_s, e.position_sigma_m[1:], e.velocity_sigma_mps]
        z = (np.r_[e.t_c_s, e.position_m[1:], e.velocity_mps] - np.r_[m.t_c_s, m.position_m[1:], m.velocity_mps]) / sig
        found[i] = (z, none, str(e.extra.get("edges")))
    return [found.get(i) or (none, none, "none") for i in range(len(ks))]


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--balls", type=int, default=60, help="balls per case (default 60)")
    ap.add_argument("--jobs", type=int, default=1, help="worker processes (default 1)")
    ap.add_argument("--cases", default=",".join(CASES), help="comma-separated case names (default all)")
    ap.add_argument("--start", default="guess", choices=("guess", "loose_fit"), help="motion the shading law is fitted at (default guess)")
    ap.add_argument("--level-samples", default="3,2", help="samples over the exposure and the pixel height of the ends' brightness (default 3,2)")
    ap.add_argument("--refined-background", action="store_true", help="every ball's edges on its columns' background away from it")
    ap.add_argument("--refit-law", action="store_true", help="the law and the limb model again at the fitted motion, and the fit again")
    ap.add_argument("--clean", action="store_true", help="also each ball's noise-free twin, in units of the noisy sigmas")
    ap.add_argument("--stream", choices=("engine", "crop"), help="measure the balls in a stream (process_stream) on this background instead of as single images")
    args = ap.parse_args(argv)
    try:
        recipe = Recipe(
            shading_start=args.start,
            level_samples=tuple(int(k) for k in args.level_samples.split(",")),
            refined_background=args.refined_background,
            refit_law=args.refit_law,
        )
    except ValueError as exc:
        ap.error(str(exc))
    names = [c for c in args.cases.split(",") if c]
    unknown = [c for c in names if c not in CASES]
    if unknown:
        ap.error(f"unknown case(s) {', '.join(unknown)}; known: {', '.join(CASES)}")
    if args.balls < 2:
        ap.error("--balls: at least 2")
    if args.stream and (args.clean or recipe != Recipe()):
        ap.error("--stream: the stream's estimator has the default shading pass and no noise-free twins")
    print(f"stream, background={args.stream!r}" if args.stream else f"recipe: {recipe}")
    print(f"z = (estimate - truth) / sigma over {args.balls} balls per case; an honest sigma: RMS 1, |mean| < {2 / np.sqrt(args.balls):.2f} (2 s.e.)")
    header = f"{'case':24s} {'lines':>5s}  " + "  ".join(f"{n:>11s}" for n in NAMES) + "  edges"
    print(header)
    print(f"{'':24s} {'':5s}  " + "  ".join(f"{'RMS  mean':>11s}" for _ in NAMES))
    for name in names:
        case = CASES[name]
        if args.stream:
            parts = [list(range(args.balls))[j :: args.jobs] for j in range(args.jobs)]
            done = Parallel(n_jobs=args.jobs)(delayed(stream_balls)(case, ks, args.stream) for ks in parts if ks)
            out = [o for part in done for o in part]
        else:
            out = Parallel(n_jobs=args.jobs)(delayed(one_ball)(case, k, recipe, args.clean) for k in range(args.balls))
        kinds = Counter(o[2] for o in out)
        for label, col in ((name, 0), (f"{name} clean", 1)):
            z = np.array([o[col] for o in out])
            ok = np.all(np.isfinite(z), axis=1)
            if col == 1 and not args.clean:
                break
            z = z[ok]
            rms = np.sqrt(np.mean(z**2, axis=0))
            mean = z.mean(axis=0)
            cells = "  ".join(f"{r:5.2f} {m:+5.2f}" for r, m in zip(rms, mean))
            tail = f"  {dict(kinds)}" if col == 0 else ""
            print(f"{label:24s} {case.lines:5.0f}  {cells}{tail}" + (f"  ({(~ok).sum()} not measured)" if (~ok).any() else ""))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
