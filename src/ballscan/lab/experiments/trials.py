"""One Monte-Carlo trial (render, measure with each method) and one sweep point's Cramér–Rao bound.

Both are picklable tasks for any worker: a trial's result depends on its
:class:`TrialSpec` only (its seed derives from the trial's identity,
:func:`trial_seed`), never on the worker or the order.
"""

from __future__ import annotations

import math
import time
import zlib
from dataclasses import dataclass, fields
from typing import Any

import numpy as np

from ...errors import BallscanError
from ...geometry.motion import BallMotion
from .config import METHODS, ExperimentConfig, Scene, appearance, crlb_noise_dn, scene_geometry

__all__ = [
    "EXTRA_FLAGS",
    "MEDIAN_ABS_NORMAL",
    "ROW_FIELDS",
    "BOUND_FIELDS",
    "TrialSpec",
    "TrialRow",
    "BoundSpec",
    "BoundRow",
    "trial_seed",
    "trial_specs",
    "pick_estimate",
    "run_trial",
    "run_bound",
]

#: Words that may appear in the CSV's ``flags`` besides geometry.md's: the
#: ball was not detected, more than one ball was detected (the one nearest the
#: true ``t_c`` is kept), the estimator raised (the message is in ``note``),
#: or the ``"pixels"`` method fell back to the plain fit (and why).
EXTRA_FLAGS = (
    "no_detection",
    "extra_detections",
    "error",
    "pixels_not_uniform",
    "pixels_lateral_motion",
    "pixels_no_start",
    "pixels_no_shading_model",
    "pixels_not_converged",
)

#: Median of |N(0, 1)|: the median absolute error of a Gaussian error of
#: 1-sigma 1.  Not the bound's median of the speed (see :class:`BoundRow`).
MEDIAN_ABS_NORMAL = 0.6744897501960817

# --------------------------------------------------------------------------- trials
@dataclass(frozen=True)
class TrialSpec:
    """One Monte-Carlo trial: a picklable task for any worker.

    Attributes
    ----------
    experiment : str
    factor : str
    value : float
    texture : str
    trial : int
        Index within the sweep point, ``0 .. trials-1``.
    scene : Scene
        The base scene with the factor applied.
    methods : tuple of str
    seed : int
        From :func:`trial_seed`.
    """

    experiment: str
    factor: str
    value: float
    texture: str
    trial: int
    scene: Scene
    methods: tuple[str, ...]
    seed: int

    @property
    def key(self) -> tuple[str, float, str, int]:
        """``(factor, value, texture, trial)``: identifies the trial in the CSV."""
        return (self.factor, float(self.value), self.texture, int(self.trial))


def trial_seed(base_seed: int, factor: str, value: float, texture: str, trial: int) -> int:
    """Seed of one trial from its identity only (never from the worker or order).

    ``numpy.random.SeedSequence`` mixes the base seed with CRC-32s of the
    factor name, the value's ``repr`` and the texture (Python's ``hash`` of a
    string differs between processes) and the trial index.
    """
    words = [int(base_seed), zlib.crc32(factor.encode()), zlib.crc32(repr(float(value)).encode()), zlib.crc32(texture.encode()), int(trial)]
    return int(np.random.SeedSequence(words).generate_state(1, dtype=np.uint32)[0])


def trial_specs(cfg: ExperimentConfig) -> list[TrialSpec]:
    """Every trial of the experiment, in a stable order."""
    out = []
    for sw in cfg.sweeps:
        for v in sw.values:
            scene = cfg.scene.with_factor(sw.factor, v)
            for tex in cfg.textures:
                for k in range(cfg.trials):
                    out.append(
                        TrialSpec(cfg.name, sw.factor, float(v), tex, k, scene, cfg.methods, trial_seed(cfg.seed, sw.factor, v, tex, k))
                    )
    return out


#: CSV columns of :class:`TrialRow`, in order.
ROW_FIELDS = (
    "experiment",
    "factor",
    "value",
    "texture",
    "trial",
    "method",
    "seed",
    "true_speed_mps",
    "est_speed_mps",
    "rel_error",
    "abs_rel_error",
    "est_vx_mps",
    "est_vy_mps",
    "est_vz_mps",
    "true_vx_mps",
    "true_vy_mps",
    "true_vz_mps",
    "run_time_s",
    "render_time_s",
    "n_lines",
    "flags",
    "note",
)


@dataclass(frozen=True)
class TrialRow:
    """One method's result on one trial (one CSV row).

    Attributes
    ----------
    rel_error : float
        ``(est - true) / true`` of the speed; NaN when no estimate was made.
    abs_rel_error : float
        ``|rel_error|``; ``inf`` when no estimate was made (a failure counts
        as the worst error in medians).
    run_time_s : float
        Seconds: ``"paper"`` and ``"fit"`` time the whole
        :func:`~ballscan.pipeline.estimate.estimate_image` call (detection included);
        ``"initial"`` times the key points and Eq. (3)-(7) only.
    render_time_s : float
        Seconds to render the trial's image (the same on each method's row).
    flags : str
        ``;``-joined words of geometry.md's flags and :data:`EXTRA_FLAGS`.
    """

    experiment: str
    factor: str
    value: float
    texture: str
    trial: int
    method: str
    seed: int
    true_speed_mps: float
    est_speed_mps: float
    rel_error: float
    abs_rel_error: float
    est_vx_mps: float
    est_vy_mps: float
    est_vz_mps: float
    true_vx_mps: float
    true_vy_mps: float
    true_vz_mps: float
    run_time_s: float
    render_time_s: float
    n_lines: int
    flags: str
    note: str = ""

    @property
    def key(self) -> tuple[str, float, str, int]:
        return (self.factor, float(self.value), self.texture, int(self.trial))

    def to_csv(self) -> list[str]:
        return [_fmt(getattr(self, f)) for f in ROW_FIELDS]

    @classmethod
    def from_csv(cls, rec: dict[str, str]) -> "TrialRow":
        kw: dict[str, Any] = {}
        for f in fields(cls):
            s = rec[f.name]
            if f.type in ("int",):
                kw[f.name] = int(s)
            elif f.type in ("float",):
                kw[f.name] = float(s)
            else:
                kw[f.name] = s
        return cls(**kw)

    def comparable(self) -> tuple:
        """Everything but the run times (equal for equal seeds whatever the workers)."""
        return tuple(getattr(self, f) for f in ROW_FIELDS if f not in ("run_time_s", "render_time_s"))


def _fmt(v: Any) -> str:
    if isinstance(v, float):
        return repr(v)
    return str(v)


def pick_estimate(report, t_c_true: float):
    """The estimate of ``report`` nearest the true crossing time ``t_c_true`` (s), and extra flags.

    Returns
    -------
    estimate or None, list of str
        None and ``["no_detection"]`` without any ball; ``["extra_detections"]``
        when more than one ball was detected.
    """
    balls = [b for b in report.balls]
    if not balls:
        return None, ["no_detection"]
    flags = ["extra_detections"] if len(balls) > 1 else []
    with_t = [b for b in balls if b.t_c_s is not None]
    best = min(with_t, key=lambda b: abs(b.t_c_s - t_c_true)) if with_t else balls[0]
    return best, flags


def run_trial(spec: TrialSpec) -> tuple[TrialRow, ...]:
    """Render one noisy image and measure it with every method of ``spec``.

    Deterministic in ``spec``: the sensor noise, the sub-line phase of
    ``t_c`` and the texture's orientation all come from ``spec.seed``.

    Returns
    -------
    tuple of TrialRow
        One per method, in :data:`METHODS` order.
    """
    from ...pipeline.estimate import estimate_image
    from ...pipeline.recipe import Recipe
    from ...measure.images import LineImage
    from ...model.render import render

    state = np.random.SeedSequence(spec.seed).generate_state(3, dtype=np.uint32)
    phase = float(state[1]) / 2.0**32 - 0.5
    geom = scene_geometry(spec.scene, phase)
    truth = geom.motion
    cam = spec.scene.camera
    t0 = time.perf_counter()
    rendered = render(
        cam,
        (truth, appearance(spec.scene, spec.texture, int(state[2]))),
        geom.n_lines,
        background_level=spec.scene.background_level,
        noise=spec.scene.noise,
        seed=int(state[0]),
    )
    t_render = time.perf_counter() - t0
    image = LineImage(rendered.image.astype(float), float(spec.scene.noise.max_dn), spec.scene.noise.bits, f"trial {spec.key}")

    results: dict[str, tuple[Any, float, list[str], str]] = {}
    # The initial guess comes with either refinement's report (same key points).
    to_run = [m for m in ("paper", "fit", "pixels") if m in spec.methods]
    if not to_run:
        to_run = ["fit"]
    for method in to_run:
        t1 = time.perf_counter()
        try:
            if method == "pixels":
                rep = estimate_image(image, cam, spec.scene.radius_m, recipe=Recipe(pixels=True))
            else:
                rep = estimate_image(image, cam, spec.scene.radius_m, recipe=Recipe(method=method))
            ball, extra = pick_estimate(rep, truth.t_c_s)
            if method == "pixels" and ball is not None and ball.extra.get("pixels") != "used":
                extra = extra + [f"pixels_{ball.extra.get('pixels')}"]
            note = ""
        except (BallscanError, ValueError, np.linalg.LinAlgError) as exc:
            # a crash of one estimator is a result of this trial, not the end of the run
            ball, extra, note = None, ["error"], f"{type(exc).__name__}: {exc}".replace("\n", " ")[:200]
        results[method] = (ball, time.perf_counter() - t1, extra, note)

    rows = []
    src = "paper" if "paper" in results else ("fit" if "fit" in results else "pixels")
    for method in METHODS:
        if method not in spec.methods:
            continue
        if method == "initial":
            ball, _, extra, note = results[src]
            t_run = float(ball.extra.get("time_initial_s", math.nan)) if ball is not None else math.nan
            est = ball.initial if ball is not None else None
            flags = list(est.flags) + extra if est is not None else extra
        else:
            ball, t_run, extra, note = results[method]
            est = ball
            flags = list(ball.flags) + extra if ball is not None else extra
        rows.append(_row(spec, method, truth, est, t_run, t_render, geom.n_lines, flags, note, int(state[0])))
    return tuple(rows)


def _row(spec: TrialSpec, method: str, truth: BallMotion, est, t_run: float, t_render: float, n_lines: int, flags, note: str, seed: int) -> TrialRow:
    s = truth.speed_mps
    if est is not None and est.speed_mps is not None and math.isfinite(est.speed_mps):
        e = float(est.speed_mps)
        rel = (e - s) / s
        v = est.velocity_mps if est.velocity_mps is not None else (math.nan,) * 3
    else:
        e, rel, v = math.nan, math.nan, (math.nan,) * 3
    return TrialRow(
        experiment=spec.experiment,
        factor=spec.factor,
        value=float(spec.value),
        texture=spec.texture,
        trial=int(spec.trial),
        method=method,
        seed=seed,
        true_speed_mps=float(s),
        est_speed_mps=e,
        rel_error=float(rel),
        abs_rel_error=abs(float(rel)) if math.isfinite(rel) else math.inf,
        est_vx_mps=float(v[0]),
        est_vy_mps=float(v[1]),
        est_vz_mps=float(v[2]),
        true_vx_mps=float(truth.velocity_mps[0]),
        true_vy_mps=float(truth.velocity_mps[1]),
        true_vz_mps=float(truth.velocity_mps[2]),
        run_time_s=float(t_run),
        render_time_s=float(t_render),
        n_lines=int(n_lines),
        flags=";".join(dict.fromkeys(flags)),
        note=note,
    )


# --------------------------------------------------------------------------- bounds
@dataclass(frozen=True)
class BoundSpec:
    """The Cramér–Rao bound task of one sweep point."""

    factor: str
    value: float
    scene: Scene


@dataclass(frozen=True)
class BoundRow:
    """Pixel Cramér–Rao bound at one sweep point (flat, untextured ball).

    Attributes
    ----------
    speed_sigma_mps : float
        RMS error of an efficient estimate's bias-corrected speed, m/s
        (:attr:`ballscan.solve.precision.PrecisionBound.speed_sigma_mps`).
    rel_sigma : float
        ``speed_sigma_mps / speed``.
    median_abs_rel : float
        The median ``|relative speed error|`` of that efficient estimate
        (:attr:`~ballscan.solve.precision.PrecisionBound.speed_abs_error_quartiles_mps`):
        the statistic plotted for the methods, and what is plotted and
        compared for the bound.  Not ``0.6745 rel_sigma``: where the depth
        velocity is the weak axis the speed's error is one-sided and
        heavy-tailed, its median far below 0.6745 of its RMS (0.14x at the
        quick Fig. 5 sweep's R = 0.02 m, 0.036x at the golf example's
        z0 = 6 m).
    q25_abs_rel, q75_abs_rel : float
        Its quartiles (the bound's band beside the methods' error bars).
    noise_dn, contrast_dn : float
        From :func:`crlb_noise_dn` (an edge pixel's white noise, for the
        record: the bound gives each pixel its own).
    prnu_sigma : float
        The columns' relative gain spread the bound includes.
    """

    factor: str
    value: float
    true_speed_mps: float
    speed_sigma_mps: float
    rel_sigma: float
    median_abs_rel: float
    q25_abs_rel: float
    q75_abs_rel: float
    noise_dn: float
    contrast_dn: float
    prnu_sigma: float

    @property
    def key(self) -> tuple[str, float]:
        return (self.factor, float(self.value))


BOUND_FIELDS = tuple(f.name for f in fields(BoundRow))


def run_bound(spec: BoundSpec) -> BoundRow:
    """Evaluate :func:`ballscan.solve.precision.sensor_crlb` at the point's nominal motion (phase 0).

    The scene's sensor model as rendered: each pixel's read, shot and
    quantisation noise, and the columns' gains (PRNU) unknown.
    """
    from ...solve.precision import sensor_crlb

    sc = spec.scene
    geom = scene_geometry(sc, 0.0)
    noise_dn, contrast_dn = crlb_noise_dn(sc)
    b = sensor_crlb(sc.camera, geom.motion, sc.noise, sc.ball_level, sc.background_level)
    s = geom.motion.speed_mps
    sig = float(b.speed_sigma_mps)
    q25, q50, q75 = (float(x) / s for x in b.speed_abs_error_quartiles_mps)
    return BoundRow(spec.factor, float(spec.value), s, sig, sig / s, q50, q25, q75, noise_dn, contrast_dn, sc.noise.prnu_sigma)
