"""Monte-Carlo reproduction of the paper's experiments (Sec. 3, Fig. 5 and Fig. 8).

An *experiment* is a base scene (camera, ball, sensor) and one-factor sweeps
of it ("control variety method", Sec. 3.A): for every swept value, every
texture and every trial a line-scan image is rendered with fresh sensor noise
and measured by each method:

``"initial"``
    the paper's key-point initial guess, Eq. (3)-(7);
``"paper"``
    the paper's gradient-image matching refinement with Powell (Eq. (9)-(10));
``"fit"``
    ballscan's sub-pixel edge least-squares fit;
``"pixels"`` (on request, not in the default set)
    the same fit with the ball's ends fitted pixel by pixel
    (``estimate_image(pixels=True)``: uniform balls and a continuous
    exposure; where it refuses a ball the row is the plain fit's, with the
    reason in ``flags`` as ``pixels_<reason>``).

The Cramér–Rao bound of the pixel intensities under the scene's sensor model
(:func:`ballscan.solve.precision.sensor_crlb`: each pixel's shot noise, the
columns' unknown gains) is added as a fourth curve.  Results are one tidy CSV row per trial and
method, a figure like Fig. 5 and a Markdown summary.

Trials are independent tasks: they run on local cores (joblib) or on a Dask
cluster, each with a seed derived from ``(seed, factor, value, texture,
trial)`` only, so results do not depend on the number of workers.  Finished
trials are appended to the CSV as they complete; a rerun with the same output
folder skips them.
"""

from __future__ import annotations

import csv
import hashlib
import json
import math
import os
import time
import tomllib
import zlib
from collections.abc import Callable, Iterable, Iterator, Sequence
from dataclasses import dataclass, field, fields, replace
from pathlib import Path
from typing import Any

import numpy as np

from ..geometry.camera import LineScanCamera, camera_from_dict, line_times, load_camera
from ..errors import BallscanError, GeometryError
from ..geometry.motion import BallMotion
from ..model.render import Appearance, SensorNoise

__all__ = [
    "ExperimentConfigError",
    "FACTORS",
    "METHODS",
    "DEFAULT_METHODS",
    "TEXTURES",
    "Scene",
    "Sweep",
    "ExperimentConfig",
    "TrialSpec",
    "TrialRow",
    "BoundRow",
    "PointSummary",
    "ExperimentResult",
    "fig5_config",
    "fig8_config",
    "load_config",
    "quick_config",
    "fig5_quick_config",
    "replace_trials",
    "config_from_dict",
    "trend_checks",
    "trial_specs",
    "trial_seed",
    "run_trial",
    "run_experiment",
    "read_rows",
    "summarise",
    "plot_sweeps",
    "plot_fig7_overlays",
    "crlb_noise_dn",
]

#: Estimators that can be compared, in plotting order.
METHODS = ("initial", "paper", "fit", "pixels")
#: Those an experiment compares unless told otherwise.
DEFAULT_METHODS = ("initial", "paper", "fit")
#: Ball surfaces: flat albedo, or the tennis seam band of :class:`ballscan.model.render.Appearance`.
TEXTURES = ("none", "tennis")
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
#: Median of |N(0, 1)|: converts a 1-sigma bound to the median absolute error
#: an efficient unbiased estimator reaches, the statistic plotted for the methods.
MEDIAN_ABS_NORMAL = 0.6744897501960817
#: Longest image a trial may render (lines); slower balls need a lower line rate.
MAX_LINES = 20000
_CSV = "trials.csv"
_BOUNDS_CSV = "bounds.csv"
_MANIFEST = "experiment.json"
_FORMAT_VERSION = 1


class ExperimentConfigError(BallscanError, ValueError):
    """An experiment configuration is invalid; the message names the file and key."""

    def __init__(self, source: str, key: str | None, problem: str):
        where = f"{source}: key '{key}'" if key else source
        super().__init__(f"{where}: {problem}")
        self.source = source
        self.key = key


# --------------------------------------------------------------------------- factors
@dataclass(frozen=True)
class FactorSpec:
    """A quantity an experiment can sweep.

    Attributes
    ----------
    name : str
        Key in configs and in the CSV's ``factor`` column (unit suffix included).
    label : str
        Axis label with the unit.
    lo, hi : float
        Allowed closed range of values.
    log_axis : bool
        Plot on a logarithmic x axis.
    """

    name: str
    label: str
    lo: float
    hi: float
    log_axis: bool = False


#: Every sweepable factor.  ``direction_deg`` tilts the velocity from the
#: viewing-plane normal towards the sensor direction +y (the lab's rotation
#: of the viewing plane about the optical axis); ``direction_z_deg`` tilts it
#: towards the depth +z.
FACTORS: dict[str, FactorSpec] = {
    f.name: f
    for f in (
        FactorSpec("radius_m", "ball radius R (m)", 1e-4, 10.0, log_axis=True),
        FactorSpec("speed_mps", "speed |V| (m/s)", 1e-4, 1e4, log_axis=True),
        FactorSpec("direction_deg", "direction towards the sensor y (deg)", -85.0, 85.0),
        FactorSpec("direction_z_deg", "direction towards the depth z (deg)", -85.0, 85.0),
        FactorSpec("line_rate_hz", "line rate (lines/s)", 1.0, 1e7, log_axis=True),
        FactorSpec("z_m", "depth z0 (m)", 1e-3, 1e4, log_axis=True),
        FactorSpec("y_m", "centre along the sensor y0 (m)", -1e4, 1e4),
        FactorSpec("read_dn", "read noise (DN)", 0.0, 1e4, log_axis=False),
        FactorSpec("ball_level", "ball grey level (linear)", 0.0, 1.0),
        FactorSpec("background_level", "background grey level (linear)", 0.0, 1.0),
    )
}


# --------------------------------------------------------------------------- configs
@dataclass(frozen=True)
class Scene:
    """Base values of an experiment (camera frame of geometry.md).

    Parameters
    ----------
    camera : LineScanCamera
        Its ``line_rate_hz`` is the base line rate.
    radius_m : float
        Ball radius, metres.
    speed_mps : float
        Speed, m/s.
    direction_deg, direction_z_deg : float
        Tilt of the velocity from the viewing-plane normal ``+x`` towards
        ``+y`` (along the sensor) and towards ``+z`` (depth), degrees:
        ``V = |V| (cos a cos b, sin a cos b, sin b)``.
    y_m, z_m : float
        Centre at ``t_c``: ``(0, y_m, z_m)``, metres.
    ball_level, background_level : float
        Linear grey levels in ``[0, 1]``.
    shading : bool
        Lambertian shading of the ball; off by default so that the untextured
        ball is the flat disc :func:`ballscan.solve.precision.sensor_crlb` bounds.
    noise : SensorNoise
        Sensor model of every trial.
    """

    camera: LineScanCamera
    radius_m: float
    speed_mps: float
    z_m: float
    direction_deg: float = 0.0
    direction_z_deg: float = 0.0
    y_m: float = 0.0
    ball_level: float = 0.7
    background_level: float = 0.1
    shading: bool = False
    noise: SensorNoise = SensorNoise()

    @property
    def velocity_mps(self) -> tuple[float, float, float]:
        """Velocity at ``t_c`` in the camera frame, m/s."""
        a, b = math.radians(self.direction_deg), math.radians(self.direction_z_deg)
        v = self.speed_mps
        return (v * math.cos(a) * math.cos(b), v * math.sin(a) * math.cos(b), v * math.sin(b))

    def with_factor(self, factor: str, value: float) -> "Scene":
        """This scene with one factor set to ``value`` (see :data:`FACTORS`)."""
        if factor == "line_rate_hz":
            cam = self.camera
            # A fixed exposure longer than the new line period is clipped to the period.
            exp = None if cam.exposure_s is None else min(cam.exposure_s, 1.0 / value)
            return replace(self, camera=replace(cam, line_rate_hz=float(value), exposure_s=exp))
        if factor == "read_dn":
            return replace(self, noise=replace(self.noise, read_dn=float(value)))
        if factor in ("radius_m", "speed_mps", "direction_deg", "direction_z_deg", "y_m", "z_m", "ball_level", "background_level"):
            return replace(self, **{factor: float(value)})
        raise ValueError(f"factor: unknown {factor!r}; choose one of {', '.join(FACTORS)}")

    def factor_value(self, factor: str) -> float:
        """The scene's value of ``factor``."""
        if factor == "line_rate_hz":
            return self.camera.line_rate_hz
        if factor == "read_dn":
            return self.noise.read_dn
        return float(getattr(self, factor))


@dataclass(frozen=True)
class Sweep:
    """One factor's values; every other factor keeps its base value."""

    factor: str
    values: tuple[float, ...]


@dataclass(frozen=True)
class ExperimentConfig:
    """A whole experiment.

    Parameters
    ----------
    name : str
        Short name (used in titles and the CSV's ``experiment`` column).
    scene : Scene
        Base values.
    sweeps : tuple of Sweep
        One-factor sweeps, one figure panel each.
    trials : int
        Monte-Carlo trials per sweep point and texture.
    textures : tuple of str
        Subset of :data:`TEXTURES`.
    methods : tuple of str
        Subset of :data:`METHODS`.
    seed : int
        Base seed; each trial's seed derives from it (:func:`trial_seed`).
    bound : bool
        Also compute the pixel Cramér–Rao bound at each sweep point.
    description : str
        One paragraph for the summary.
    source : str
        Where the config came from (for messages).
    """

    name: str
    scene: Scene
    sweeps: tuple[Sweep, ...]
    trials: int = 16
    textures: tuple[str, ...] = TEXTURES
    methods: tuple[str, ...] = DEFAULT_METHODS
    seed: int = 0
    bound: bool = True
    description: str = ""
    source: str = field(default="<config>", compare=False)

    def __post_init__(self) -> None:
        validate_config(self)

    def fingerprint(self) -> str:
        """Hash of everything that changes a trial's result (not the sweep list or trial count).

        Rows of a previous run are reused only when the fingerprints agree.
        """
        d = {
            "version": _FORMAT_VERSION,
            "scene": _scene_dict(self.scene),
            "methods": sorted(self.methods),
            "seed": self.seed,
        }
        return hashlib.sha256(json.dumps(d, sort_keys=True).encode()).hexdigest()[:16]


def _scene_dict(scene: Scene) -> dict[str, Any]:
    d = {f.name: getattr(scene, f.name) for f in fields(scene) if f.name not in ("camera", "noise")}
    d["camera"] = scene.camera.to_dict()
    d["noise"] = scene.noise.to_dict()
    return d


def validate_config(cfg: ExperimentConfig) -> None:
    """Check a config before any work; raise :class:`ExperimentConfigError` naming the key.

    Besides the ranges of every value, each sweep point's ball must be imaged
    wholly inside the sensor in fewer than :data:`MAX_LINES` lines.
    """
    src = cfg.source

    def bad(key: str, problem: str) -> ExperimentConfigError:
        return ExperimentConfigError(src, key, problem)

    if isinstance(cfg.trials, bool) or not isinstance(cfg.trials, (int, np.integer)) or cfg.trials < 1:
        raise bad("trials", f"must be a positive integer, got {cfg.trials!r}")
    if isinstance(cfg.seed, bool) or not isinstance(cfg.seed, (int, np.integer)) or cfg.seed < 0:
        raise bad("seed", f"must be a non-negative integer, got {cfg.seed!r}")
    if not cfg.textures or any(t not in TEXTURES for t in cfg.textures) or len(set(cfg.textures)) != len(cfg.textures):
        raise bad("textures", f"must be distinct words of {list(TEXTURES)}, got {list(cfg.textures)}")
    if not cfg.methods or any(m not in METHODS for m in cfg.methods) or len(set(cfg.methods)) != len(cfg.methods):
        raise bad("methods", f"must be distinct words of {list(METHODS)}, got {list(cfg.methods)}")
    if not cfg.sweeps:
        raise bad("sweep", "at least one sweep is needed")
    seen = set()
    for k, sw in enumerate(cfg.sweeps):
        key = f"sweep[{k}]"
        if sw.factor not in FACTORS:
            raise bad(f"{key}.factor", f"unknown factor {sw.factor!r}; choose one of {', '.join(FACTORS)}")
        if sw.factor in seen:
            raise bad(f"{key}.factor", f"{sw.factor!r} is swept twice")
        seen.add(sw.factor)
        if len(sw.values) == 0:
            raise bad(f"{key}.values", "empty range")
        spec = FACTORS[sw.factor]
        for v in sw.values:
            if not (isinstance(v, (int, float, np.floating, np.integer)) and math.isfinite(v) and spec.lo <= v <= spec.hi):
                raise bad(f"{key}.values", f"{sw.factor} = {v!r} is outside [{spec.lo:g}, {spec.hi:g}]")
        if len(set(sw.values)) != len(sw.values):
            raise bad(f"{key}.values", "repeated value")
    _check_scene(cfg.scene, src, "ball")
    for k, sw in enumerate(cfg.sweeps):
        for v in sw.values:
            try:
                _check_scene(cfg.scene.with_factor(sw.factor, v), src, f"sweep[{k}]")
            except ExperimentConfigError as exc:
                raise bad(f"sweep[{k}].values", f"{sw.factor} = {v:g}: {str(exc).split(': ', 2)[-1]}") from None
            except (ValueError, GeometryError) as exc:
                raise bad(f"sweep[{k}].values", f"{sw.factor} = {v:g}: {exc}") from None


def _check_scene(scene: Scene, src: str, key: str) -> None:
    """Ranges of the base values and the ball's image within the sensor."""
    for name in ("radius_m", "speed_mps", "z_m"):
        v = getattr(scene, name)
        if not (math.isfinite(v) and v > 0):
            raise ExperimentConfigError(src, f"{key}.{name}", f"must be positive, got {v!r}")
    for name in ("direction_deg", "direction_z_deg", "y_m", "ball_level", "background_level"):
        spec = FACTORS[name]
        v = getattr(scene, name)
        if not (math.isfinite(v) and spec.lo <= v <= spec.hi):
            raise ExperimentConfigError(src, f"{key}.{name}", f"{v!r} is outside [{spec.lo:g}, {spec.hi:g}]")
    if abs(scene.ball_level - scene.background_level) < 0.02:
        raise ExperimentConfigError(src, f"{key}.ball_level", "ball and background levels must differ by at least 0.02")
    if scene.z_m <= scene.radius_m:
        raise ExperimentConfigError(src, f"{key}.z_m", f"the camera would be inside the ball (z_m = {scene.z_m:g} <= radius_m)")
    geom = scene_geometry(scene, phase=0.0)
    if geom.n_lines > MAX_LINES:
        raise ExperimentConfigError(
            src, key, f"the ball needs {geom.n_lines} lines (> {MAX_LINES}); raise the speed or lower the line rate"
        )
    from ..model.silhouette import silhouette

    sil = silhouette(scene.camera, geom.motion, line_times(scene.camera, geom.n_lines))
    if not np.any(sil.present):
        raise ExperimentConfigError(src, key, "the ball is not seen on any line")
    lo = float(np.nanmin(sil.left_px[sil.present]))
    hi = float(np.nanmax(sil.right_px[sil.present]))
    if lo < 2 or hi > scene.camera.width - 3:
        raise ExperimentConfigError(
            src, key, f"the ball's image spans pixels {lo:.0f}..{hi:.0f}, outside the sensor 0..{scene.camera.width - 1}"
        )


# --------------------------------------------------------------------------- geometry of a trial
@dataclass(frozen=True)
class TrialGeometry:
    """The true motion of one trial and the image size.

    Attributes
    ----------
    motion : BallMotion
        True motion; ``t_c`` lies half-way through the image, offset by the
        trial's sub-line phase.
    n_lines : int
        Image height: the visible lines plus a 15 % + 6 line margin at each end.
    """

    motion: BallMotion
    n_lines: int


def scene_geometry(scene: Scene, phase: float) -> TrialGeometry:
    """Image size and true motion for a scene.

    Parameters
    ----------
    scene : Scene
    phase : float
        Offset of ``t_c`` from the middle line in line periods, ``[-0.5, 0.5)``:
        random per trial so that the errors average over where the ball's
        crossing falls between two lines.
    """
    from ..model.silhouette import visible_line_count

    m0 = BallMotion(scene.radius_m, 0.0, (0.0, scene.y_m, scene.z_m), scene.velocity_mps)
    visible = visible_line_count(scene.camera, m0)
    if not math.isfinite(visible):
        raise GeometryError("the ball never crosses the viewing plane (V.x = 0)")
    margin = int(math.ceil(0.15 * visible)) + 6
    n_lines = int(math.ceil(visible)) + 2 * margin
    t_c = (0.5 * (n_lines - 1) + phase) / scene.camera.line_rate_hz
    return TrialGeometry(BallMotion(scene.radius_m, t_c, m0.position_m, m0.velocity_mps), n_lines)


def appearance(scene: Scene, texture: str, orientation_seed: int) -> Appearance:
    """The ball's look: flat albedo, or the tennis seam at a random orientation."""
    if texture == "none":
        return Appearance(ball_level=scene.ball_level, shading=scene.shading, texture="none")
    # seam brighter than a dark felt, darker than a bright one: always visible
    seam = 0.95 if scene.ball_level < 0.8 else 0.4
    return Appearance(ball_level=scene.ball_level, shading=scene.shading, texture="tennis", seam_level=seam, orientation_seed=orientation_seed)


def crlb_noise_dn(scene: Scene) -> tuple[float, float]:
    """White noise of an edge pixel and the contrast (DN), for the record.

    ``sigma^2 = read_dn^2 + Y_mid white_dn^2 / full_well_e + 1/12`` with
    ``Y_mid = (ball_level + background_level) / 2`` (read, shot and uniform
    quantisation noise of a pixel half ball and half background).  The
    bound itself (:func:`run_bound`, :func:`ballscan.solve.precision.sensor_crlb`)
    gives every pixel its own shot noise and includes the columns' unknown
    gains (PRNU).

    Returns
    -------
    noise_dn, contrast_dn : float
    """
    n = scene.noise
    y_mid = 0.5 * (scene.ball_level + scene.background_level)
    shot = y_mid * n.white_dn**2 / n.full_well_e if n.full_well_e else 0.0
    var = n.read_dn**2 + shot + 1.0 / 12.0
    return math.sqrt(var), abs(scene.ball_level - scene.background_level) * n.white_dn


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


def _pick(report, t_c_true: float):
    """The estimate nearest the true crossing time, and extra flags."""
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
    from ..pipeline.estimate import estimate_image
    from ..pipeline.recipe import Recipe
    from ..measure.images import LineImage
    from ..model.render import render

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
            ball, extra = _pick(rep, truth.t_c_s)
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
        1-sigma bound on the speed, m/s.
    rel_sigma : float
        ``speed_sigma_mps / speed``.
    median_abs_rel : float
        ``0.6745 rel_sigma``: the median ``|relative error|`` an efficient
        unbiased estimator reaches (what is plotted and compared).
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
    from ..solve.precision import sensor_crlb

    sc = spec.scene
    geom = scene_geometry(sc, 0.0)
    noise_dn, contrast_dn = crlb_noise_dn(sc)
    b = sensor_crlb(sc.camera, geom.motion, sc.noise, sc.ball_level, sc.background_level)
    s = geom.motion.speed_mps
    sig = float(b.speed_sigma_mps)
    return BoundRow(spec.factor, float(spec.value), s, sig, sig / s, MEDIAN_ABS_NORMAL * sig / s, noise_dn, contrast_dn, sc.noise.prnu_sigma)


# --------------------------------------------------------------------------- execution
def _execute(func: Callable[[Any], Any], items: Sequence[Any], jobs: int, scheduler: str | None, label: str, progress: bool) -> Iterator[Any]:
    """Yield ``func(item)`` for every item, in completion order.

    ``scheduler`` (a Dask scheduler address) sends the tasks to a Dask
    cluster; otherwise ``jobs`` local processes run them (joblib's loky
    backend; ``jobs == 1`` runs in this process).
    """
    if not items:
        return
    bar = _Progress(progress, label, len(items))
    with bar as advance:
        if scheduler is not None:
            yield from _execute_dask(func, items, scheduler, advance)
        elif jobs == 1:
            for it in items:
                r = func(it)
                advance()
                yield r
        else:
            import joblib
            from joblib import Parallel, delayed

            # completion order (joblib >= 1.4) lets finished trials reach the CSV at once;
            # joblib 1.3 can only return them in submission order
            major, minor = (int(x) for x in joblib.__version__.split(".")[:2])
            mode = "generator_unordered" if (major, minor) >= (1, 4) else "generator"
            par = Parallel(n_jobs=jobs, return_as=mode, batch_size=1)
            for r in par(delayed(func)(it) for it in items):
                advance()
                yield r


def _execute_dask(func, items, scheduler: str, advance) -> Iterator[Any]:
    try:
        from distributed import Client, as_completed
    except ImportError:
        raise BallscanError(
            "--scheduler needs Dask's distributed scheduler, which is not installed: pip install 'ballscan[dask]' (or 'dask[distributed]')"
        ) from None
    try:
        client = Client(scheduler, set_as_default=False, timeout="20s")
    except (OSError, TimeoutError) as exc:
        raise BallscanError(f"--scheduler {scheduler}: cannot connect ({exc})") from None
    try:
        # pure=False: identical specs never occur, and hashing them is wasted work
        futures = client.map(func, list(items), pure=False)
        # as_completed finds its event loop through the current client
        with client.as_current():
            for fut in as_completed(futures):
                r = fut.result()
                advance()
                yield r
    finally:
        client.close()


class _Progress:
    """A rich progress bar (or nothing); ``with`` yields the advance callback."""

    def __init__(self, enabled: bool, label: str, total: int):
        self.enabled, self.label, self.total = enabled, label, total
        self._p = None

    def __enter__(self):
        if not self.enabled:
            return lambda: None
        from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn, TimeRemainingColumn

        self._p = Progress(TextColumn("{task.description}"), BarColumn(), MofNCompleteColumn(), TimeElapsedColumn(), TimeRemainingColumn())
        self._p.start()
        task = self._p.add_task(self.label, total=self.total)
        return lambda: self._p.advance(task)

    def __exit__(self, *exc) -> None:
        if self._p is not None:
            self._p.stop()


# --------------------------------------------------------------------------- CSV I/O
def read_rows(path: str | Path) -> list[TrialRow]:
    """Rows of a trials CSV; a truncated last line (an interrupted write) is ignored."""
    path = Path(path)
    if not path.exists():
        return []
    rows = []
    with path.open(newline="") as fh:
        reader = csv.DictReader(fh)
        if reader.fieldnames is None:
            return []
        if tuple(reader.fieldnames) != ROW_FIELDS:
            raise BallscanError(f"{path}: not a ballscan trials CSV (columns {reader.fieldnames})")
        for rec in reader:
            try:
                rows.append(TrialRow.from_csv(rec))
            except (TypeError, ValueError, KeyError):
                continue
    return rows


def _complete_trials(rows: Iterable[TrialRow], methods: Sequence[str]) -> dict[tuple, list[TrialRow]]:
    by: dict[tuple, list[TrialRow]] = {}
    for r in rows:
        by.setdefault(r.key, []).append(r)
    need = set(methods)
    return {k: v for k, v in by.items() if {r.method for r in v} == need and len(v) == len(need)}


def _write_csv(path: Path, header: Sequence[str], rows: Iterable[list[str]]) -> None:
    tmp = path.with_suffix(path.suffix + ".tmp")
    with tmp.open("w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(header)
        w.writerows(rows)
    os.replace(tmp, path)


def _read_bounds(path: Path) -> list[BoundRow]:
    if not path.exists():
        return []
    out = []
    with path.open(newline="") as fh:
        for rec in csv.DictReader(fh):
            try:
                out.append(BoundRow(rec["factor"], *(float(rec[k]) for k in BOUND_FIELDS[1:])))
            except (TypeError, ValueError, KeyError):
                continue
    return out


# --------------------------------------------------------------------------- summary
@dataclass(frozen=True)
class PointSummary:
    """Statistics of one method at one sweep point and texture.

    Attributes
    ----------
    n : int
        Trials.
    n_failed : int
        Trials without a speed estimate (counted as infinite error).
    median_abs_rel : float
        Median ``|relative speed error|`` (dimensionless).
    q25_abs_rel, q75_abs_rel : float
        Inter-quartile range of ``|relative speed error|`` (the error bars).
    median_rel : float
        Median signed relative error (bias), over successful trials.
    median_run_time_s : float
    """

    factor: str
    value: float
    texture: str
    method: str
    n: int
    n_failed: int
    median_abs_rel: float
    q25_abs_rel: float
    q75_abs_rel: float
    median_rel: float
    median_run_time_s: float


def summarise(rows: Sequence[TrialRow]) -> list[PointSummary]:
    """Per (factor, value, texture, method) statistics, sorted."""
    groups: dict[tuple, list[TrialRow]] = {}
    for r in rows:
        groups.setdefault((r.factor, r.value, r.texture, r.method), []).append(r)
    out = []
    for (f, v, t, m), g in sorted(groups.items(), key=lambda kv: (kv[0][0], kv[0][1], kv[0][2], METHODS.index(kv[0][3]))):
        a = np.array([r.abs_rel_error for r in g])
        rel = np.array([r.rel_error for r in g])
        rel = rel[np.isfinite(rel)]
        tt = np.array([r.run_time_s for r in g])
        tt = tt[np.isfinite(tt)]
        q25, med, q75 = np.quantile(a, [0.25, 0.5, 0.75], method="linear") if np.all(np.isfinite(a)) else _inf_quantiles(a)
        out.append(
            PointSummary(
                f, v, t, m, len(g), int(np.sum(~np.isfinite(a))), float(med), float(q25), float(q75),
                float(np.median(rel)) if rel.size else math.nan, float(np.median(tt)) if tt.size else math.nan,
            )
        )
    return out


def _inf_quantiles(a: np.ndarray) -> tuple[float, float, float]:
    # np.quantile interpolates inf - finite to nan; order statistics keep inf
    s = np.sort(a)
    n = len(s)
    return tuple(float(s[min(n - 1, int(math.floor(q * (n - 1) + 0.5)))]) for q in (0.25, 0.5, 0.75))  # type: ignore[return-value]


# --------------------------------------------------------------------------- runner
@dataclass(frozen=True)
class ExperimentResult:
    """What :func:`run_experiment` produced.

    Attributes
    ----------
    config : ExperimentConfig
    out_dir : Path
    rows : tuple of TrialRow
        Every row of the config's trials (previous runs included), sorted by key.
    bounds : tuple of BoundRow
    summary : tuple of PointSummary
    n_new_trials, n_reused_trials : int
        Trials run now and trials taken from an earlier run's CSV.
    wall_time_s : float
        Wall-clock seconds of this call.
    files : tuple of Path
        CSV, bounds CSV, summary CSV, figure(s) and Markdown summary written.
    """

    config: ExperimentConfig
    out_dir: Path
    rows: tuple[TrialRow, ...]
    bounds: tuple[BoundRow, ...]
    summary: tuple[PointSummary, ...]
    n_new_trials: int
    n_reused_trials: int
    wall_time_s: float
    files: tuple[Path, ...]

    def stat(self, factor: str, value: float, texture: str, method: str) -> PointSummary:
        """The summary of one point (``KeyError`` if absent)."""
        for s in self.summary:
            if (s.factor, s.value, s.texture, s.method) == (factor, float(value), texture, method):
                return s
        raise KeyError((factor, value, texture, method))

    def bound(self, factor: str, value: float) -> BoundRow:
        for b in self.bounds:
            if b.key == (factor, float(value)):
                return b
        raise KeyError((factor, value))


def _default_jobs() -> int:
    return max(1, len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else (os.cpu_count() or 1))


def run_experiment(
    cfg: ExperimentConfig,
    out_dir: str | Path,
    *,
    jobs: int | None = None,
    scheduler: str | None = None,
    progress: bool = True,
    fresh: bool = False,
    plots: bool = True,
    command: str | None = None,
    overlays: bool = False,
    quick: bool = False,
) -> ExperimentResult:
    """Run (or resume) an experiment and write its CSV, figure and summary.

    Parameters
    ----------
    cfg : ExperimentConfig
    out_dir : path
        Output folder; created if needed.  If it holds a run of the same
        configuration (same :meth:`ExperimentConfig.fingerprint`) its
        finished trials are kept and skipped.
    jobs : int, optional
        Local worker processes (default: every core available); ignored with
        ``scheduler``.
    scheduler : str, optional
        Address of a Dask scheduler (``tcp://host:8786``) to run the trials on.
    progress : bool
        Show rich progress bars.
    fresh : bool
        Discard any earlier results in ``out_dir``.
    plots : bool
        Write the figure (matplotlib) besides the CSVs and the summary.
    command : str, optional
        The command line, quoted in the summary.
    overlays : bool
        Also render Fig. 7-like overlays (one image per sweep point).
    quick : bool
        Say in the summary that this is the reduced ``--quick`` run.

    Returns
    -------
    ExperimentResult

    Raises
    ------
    BallscanError
        If ``out_dir`` holds a different experiment, or Dask is needed but missing.
    """
    t_start = time.perf_counter()
    if jobs is None:
        jobs = _default_jobs()
    if isinstance(jobs, bool) or not isinstance(jobs, int) or jobs < 1:
        raise ValueError(f"jobs: must be a positive integer, got {jobs!r}")
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    csv_path, bounds_path, manifest = out / _CSV, out / _BOUNDS_CSV, out / _MANIFEST
    fp = cfg.fingerprint()
    if fresh:
        for p in (csv_path, bounds_path, manifest):
            p.unlink(missing_ok=True)
    if manifest.exists():
        try:
            old = json.loads(manifest.read_text()).get("fingerprint")
        except (json.JSONDecodeError, AttributeError):
            old = None
        if old != fp:
            raise BallscanError(f"{out}: holds results of a different experiment configuration; use another --out or --fresh")
    manifest.write_text(json.dumps({"fingerprint": fp, "name": cfg.name, "scene": _scene_dict(cfg.scene), "methods": list(cfg.methods), "seed": cfg.seed}, indent=2))

    specs = trial_specs(cfg)
    wanted = {s.key for s in specs}
    done = _complete_trials(read_rows(csv_path), cfg.methods)
    # Rewrite the CSV with complete trials only: a trial cut short by an
    # interruption has some of its rows and is redone whole.
    kept = [r for k in sorted(done) for r in sorted(done[k], key=lambda r: METHODS.index(r.method))]
    _write_csv(csv_path, ROW_FIELDS, (r.to_csv() for r in kept))
    todo = [s for s in specs if s.key not in done]
    n_reused = len(wanted & set(done))

    new_rows: list[TrialRow] = []
    with csv_path.open("a", newline="") as fh:
        writer = csv.writer(fh)
        for rows in _execute(run_trial, todo, jobs, scheduler, f"{cfg.name}: trials", progress):
            # one write per trial, flushed, so an interruption loses at most the trials in flight
            writer.writerows(r.to_csv() for r in rows)
            fh.flush()
            new_rows.extend(rows)

    bounds: list[BoundRow] = []
    if cfg.bound:
        have = {b.key: b for b in _read_bounds(bounds_path)}
        points = [(sw.factor, float(v)) for sw in cfg.sweeps for v in sw.values]
        todo_b = [BoundSpec(f, v, cfg.scene.with_factor(f, v)) for f, v in points if (f, v) not in have]
        for b in _execute(run_bound, todo_b, jobs, scheduler, f"{cfg.name}: Cramér–Rao bounds", progress):
            have[b.key] = b
        _write_csv(bounds_path, BOUND_FIELDS, ([_fmt(getattr(b, k)) for k in BOUND_FIELDS] for b in sorted(have.values(), key=lambda b: b.key)))
        bounds = [have[p] for p in points]

    all_rows = [r for r in kept if r.key in wanted] + new_rows
    all_rows.sort(key=lambda r: (r.key, METHODS.index(r.method)))
    summary = summarise(all_rows)
    wall = time.perf_counter() - t_start
    result = ExperimentResult(cfg, out, tuple(all_rows), tuple(bounds), tuple(summary), len(todo), n_reused, wall, ())
    files = [csv_path] + ([bounds_path] if cfg.bound else [])
    files.append(_write_summary_csv(result))
    if plots:
        files.append(plot_sweeps(result, out / f"{cfg.name}.png"))
        if overlays:
            files.append(plot_fig7_overlays(cfg, out / f"{cfg.name}-overlays.png"))
    wall = time.perf_counter() - t_start
    result = replace(result, wall_time_s=wall, files=tuple(files))
    md = out / "summary.md"
    md.write_text(summary_markdown(result, command=command, quick=quick))
    return replace(result, files=tuple(files) + (md,))


def _write_summary_csv(res: ExperimentResult) -> Path:
    path = res.out_dir / "summary.csv"
    names = [f.name for f in fields(PointSummary)]
    _write_csv(path, names, ([_fmt(getattr(s, n)) for n in names] for s in res.summary))
    return path


# --------------------------------------------------------------------------- reporting
def _pct(x: float) -> str:
    if not math.isfinite(x):
        return "fail"
    return f"{100 * x:.3g}"


def trend_checks(res: ExperimentResult) -> list[str]:
    """The paper's claims (Sec. 3.A) checked on these results, one sentence each."""
    out = []
    cfg = res.config
    ms = [m for m in ("paper", "fit") if m in cfg.methods]
    for tex in cfg.textures:
        if "initial" in cfg.methods:
            for m in ms:
                pts = [(s, res.stat(s.factor, s.value, tex, "initial")) for s in res.summary if s.texture == tex and s.method == m]
                better = sum(1 for a, b in pts if a.median_abs_rel < b.median_abs_rel)
                out.append(f"[{tex}] {m} better than the initial guess (median |error|) at {better} of {len(pts)} sweep points.")
        for sw in cfg.sweeps:
            if len(sw.values) < 2:
                continue
            lo, hi = min(sw.values), max(sw.values)
            for m in ms:
                a = res.stat(sw.factor, lo, tex, m).median_abs_rel
                b = res.stat(sw.factor, hi, tex, m).median_abs_rel
                ratio = b / a if a > 0 and math.isfinite(a) and math.isfinite(b) else math.nan
                out.append(f"[{tex}] {m}: median |error| at {sw.factor} = {hi:g} is {ratio:.3g} x that at {lo:g}.")
    return out


def summary_markdown(res: ExperimentResult, command: str | None = None, quick: bool = False) -> str:
    """A short Markdown report: settings, table of median errors, the paper's trends checked."""
    cfg = res.config
    sc = cfg.scene
    lines = [f"# Experiment `{cfg.name}`", ""]
    if quick:
        lines += [f"**Quick mode**: {cfg.trials} trials per point, {sum(len(s.values) for s in cfg.sweeps)} points, methods {', '.join(cfg.methods)}. Numbers are indicative only.", ""]
    if cfg.description:
        lines += [cfg.description, ""]
    if command:
        lines += ["Command:", "", f"    {command}", ""]
    v = sc.velocity_mps
    lines += [
        "## Base scene",
        "",
        f"- camera: {sc.camera.width} px, f = {sc.camera.focal_px:g} px, c = {sc.camera.principal_px:g} px, "
        f"{sc.camera.line_rate_hz:g} lines/s, exposure {sc.camera.exposure * 1e6:.4g} us",
        f"- ball: R = {sc.radius_m:g} m, |V| = {sc.speed_mps:g} m/s, direction {sc.direction_deg:g} deg towards y and "
        f"{sc.direction_z_deg:g} deg towards z (V = {v[0]:.4g}, {v[1]:.4g}, {v[2]:.4g} m/s), centre (0, {sc.y_m:g}, {sc.z_m:g}) m",
        f"- levels: ball {sc.ball_level:g}, background {sc.background_level:g} (linear), shading {'on' if sc.shading else 'off'}",
        f"- sensor: {sc.noise.bits} bit, white {sc.noise.white_dn:g} DN, read noise {sc.noise.read_dn:g} DN, full well "
        f"{sc.noise.full_well_e} e-, PRNU {sc.noise.prnu_sigma:g}",
        "- sweeps: " + "; ".join(f"{s.factor} in {list(s.values)}" for s in cfg.sweeps),
        f"- {cfg.trials} trials per point and texture ({', '.join(cfg.textures)}), seed {cfg.seed}; methods {', '.join(cfg.methods)}"
        + ("; Cramér–Rao bound of the pixels" if cfg.bound else ""),
        "",
        f"Run: {res.n_new_trials} trials now, {res.n_reused_trials} reused from an earlier run, {res.wall_time_s:.1f} s wall "
        f"this call; median run time per ball: "
        + ", ".join(f"{m} {1e3 * _median([s.median_run_time_s for s in res.summary if s.method == m]):.0f} ms" for m in cfg.methods)
        + ".",
        "",
        "## Median |relative speed error| (%)",
        "",
        "Median over the trials; in brackets the inter-quartile range; `fail` = more than half the trials gave no speed. "
        "CRLB = 0.6745 x the pixel Cramér–Rao 1-sigma bound (what an efficient unbiased estimator's median |error| would be, "
        "for the untextured flat ball, under the sensor's read, shot and quantisation noise and its columns' unknown gains).",
        "",
    ]
    head = ["factor", "value", "texture"] + list(cfg.methods) + (["CRLB"] if cfg.bound else []) + ["failed"]
    lines.append("| " + " | ".join(head) + " |")
    lines.append("|" + "---|" * len(head))
    bmap = {b.key: b for b in res.bounds}
    for sw in cfg.sweeps:
        for val in sw.values:
            for tex in cfg.textures:
                cells = [sw.factor, f"{val:g}", tex]
                failed = []
                for m in cfg.methods:
                    s = res.stat(sw.factor, val, tex, m)
                    cells.append(f"{_pct(s.median_abs_rel)} [{_pct(s.q25_abs_rel)}–{_pct(s.q75_abs_rel)}]")
                    if s.n_failed:
                        failed.append(f"{m} {s.n_failed}/{s.n}")
                if cfg.bound:
                    b = bmap.get((sw.factor, float(val)))
                    cells.append(_pct(b.median_abs_rel) if b else "-")
                cells.append(", ".join(failed) or "0")
                lines.append("| " + " | ".join(cells) + " |")
    lines += ["", "## The paper's trends, checked", ""]
    lines += [f"- {t}" for t in trend_checks(res)]
    lines.append("")
    return "\n".join(lines)


def _median(xs: Sequence[float]) -> float:
    a = np.array([x for x in xs if math.isfinite(x)])
    return float(np.median(a)) if a.size else math.nan


_COLOURS = {"initial": "tab:red", "paper": "tab:green", "fit": "tab:blue", "pixels": "tab:purple"}
_LABELS = {
    "initial": "initial guess (Eq. 3-7)",
    "paper": "paper refinement (Powell)",
    "fit": "least-squares fit",
    "pixels": "fit of the ends' pixels",
}


def plot_sweeps(res: ExperimentResult, path: str | Path | None = None, axes=None):
    """Relative speed error against each swept factor, like the paper's Fig. 5.

    One column per sweep, one row per texture; one line per method (median
    ``|relative error|`` over the trials, error bars the inter-quartile
    range) and the Cramér–Rao curve (dashed).

    Parameters
    ----------
    res : ExperimentResult
    path : path, optional
        Write a PNG there (150 dpi).
    axes : array of matplotlib Axes, optional
        ``(n_textures, n_sweeps)`` axes to draw into.

    Returns
    -------
    Path or matplotlib.figure.Figure
        ``path`` when given (the figure is closed), else the figure.
    """
    import matplotlib

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt
    import matplotlib.ticker as mticker

    cfg = res.config
    nr, nc = len(cfg.textures), len(cfg.sweeps)
    if axes is None:
        fig, axes = plt.subplots(nr, nc, figsize=(3.6 * nc, 3.2 * nr), squeeze=False, sharey="row")
    else:
        axes = np.asarray(axes).reshape(nr, nc)
        fig = axes[0, 0].figure
    bmap = {b.key: b for b in res.bounds}
    for i, tex in enumerate(cfg.textures):
        for j, sw in enumerate(cfg.sweeps):
            ax = axes[i, j]
            xs = np.array(sorted(sw.values))
            for m in cfg.methods:
                st = [res.stat(sw.factor, x, tex, m) for x in xs]
                med = np.array([s.median_abs_rel for s in st])
                lo = np.array([s.q25_abs_rel for s in st])
                hi = np.array([s.q75_abs_rel for s in st])
                # failed majorities (infinite medians) and exact zeros cannot be drawn on a log axis
                ok = np.isfinite(med) & (med > 0)
                top = np.where(np.isfinite(hi[ok]), hi[ok], med[ok])
                yerr = np.vstack([med[ok] - lo[ok], top - med[ok]])
                ax.errorbar(xs[ok], med[ok], yerr=yerr, color=_COLOURS[m], marker="o", ms=3.5, lw=1.2, capsize=2, label=_LABELS[m])
                for x, s in zip(xs, st):
                    if s.n_failed:
                        # one line per method near the top, so that several methods' notes do not overlap
                        y = 0.97 - 0.07 * METHODS.index(m)
                        ax.annotate(f"{m}: {s.n_failed}/{s.n} failed", (x, y), xycoords=("data", "axes fraction"), fontsize=6,
                                    color=_COLOURS[m], ha="left", va="top")
            if cfg.bound:
                yb = np.array([bmap[(sw.factor, float(x))].median_abs_rel if (sw.factor, float(x)) in bmap else np.nan for x in xs])
                ax.plot(xs, yb, "k--", lw=1.0, label="Cramér–Rao (0.67 sigma)")
            ax.set_yscale("log")
            if FACTORS[sw.factor].log_axis:
                ax.set_xscale("log")
                # plain numbers at 1-2-5 steps read better than powers of ten
                ax.xaxis.set_major_locator(mticker.LogLocator(base=10, subs=(1.0, 2.0, 5.0)))
                ax.xaxis.set_major_formatter(mticker.FuncFormatter(lambda x, _: f"{x / 1000:g}k" if x >= 1000 else f"{x:g}"))
                ax.xaxis.set_minor_formatter(mticker.NullFormatter())
            ax.grid(True, which="both", alpha=0.25)
            ax.set_xlabel(FACTORS[sw.factor].label)
            base = cfg.scene.factor_value(sw.factor)
            ax.axvline(base, color="0.6", lw=0.8, ls=":")
            if j == 0:
                ax.set_ylabel(f"|relative speed error|\n({'untextured' if tex == 'none' else 'tennis texture'})")
    axes[0, 0].legend(fontsize=7, loc="best")
    fig.suptitle(f"{cfg.name}: median |relative speed error| over {cfg.trials} trials (bars: inter-quartile range)", fontsize=10)
    fig.tight_layout()
    if path is None:
        return fig
    fig.savefig(path, dpi=150)
    plt.close(fig)
    return Path(path)


def plot_fig7_overlays(cfg: ExperimentConfig, path: str | Path, texture: str | None = None) -> Path:
    """One rendered image per sweep point with the estimated contours, like Fig. 7.

    Trial 0 of each point is rendered (same seed as in the CSV) and measured
    with the paper's method (top row) and the fit (bottom row); red is the
    initial guess, green the refined estimate
    (:func:`ballscan.pipeline.plot.plot_estimates`).
    """
    import matplotlib

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    from ..pipeline.estimate import estimate_image
    from ..pipeline.recipe import Recipe
    from ..measure.images import LineImage
    from ..pipeline.plot import plot_estimates
    from ..model.render import render

    tex = texture or cfg.textures[-1]
    points = [(sw.factor, v) for sw in cfg.sweeps for v in sw.values]
    methods = [m for m in ("paper", "fit") if m in cfg.methods] or ["fit"]
    fig, axes = plt.subplots(len(methods), len(points), figsize=(2.6 * len(points), 3.2 * len(methods)), squeeze=False)
    for j, (f, v) in enumerate(points):
        scene = cfg.scene.with_factor(f, v)
        seed = trial_seed(cfg.seed, f, v, tex, 0)
        state = np.random.SeedSequence(seed).generate_state(3, dtype=np.uint32)
        geom = scene_geometry(scene, float(state[1]) / 2.0**32 - 0.5)
        r = render(scene.camera, (geom.motion, appearance(scene, tex, int(state[2]))), geom.n_lines,
                   background_level=scene.background_level, noise=scene.noise, seed=int(state[0]))
        img = LineImage(r.image.astype(float), float(scene.noise.max_dn), scene.noise.bits, "overlay")
        t = line_times(scene.camera, geom.n_lines)
        for i, m in enumerate(methods):
            rep = estimate_image(img, scene.camera, scene.radius_m, recipe=Recipe(method=m))
            ax = axes[i, j]
            plot_estimates(img.data, scene.camera, rep, t, ax=ax, margin_px=15)
            s = rep.balls[0].speed_mps if rep.balls and rep.balls[0].speed_mps is not None else math.nan
            err = (s - geom.motion.speed_mps) / geom.motion.speed_mps
            ax.set_title(f"{f} = {v:g}\n{m}: error {100 * err:+.2f} %", fontsize=8)
            ax.tick_params(labelsize=6)
            ax.xaxis.label.set_size(7)
            ax.yaxis.label.set_size(7)
    fig.suptitle(f"{cfg.name}: trial 0 of each point ({tex} texture); red initial guess, green refined", fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)
    return Path(path)


# --------------------------------------------------------------------------- built-in experiments
def _fig5_scene() -> Scene:
    # A BASLER spL2048-like sensor behind a 40 mm lens (10 um pixels -> f = 4000 px).
    cam = LineScanCamera(width=2048, focal_px=4000.0, principal_px=1023.5, line_rate_hz=35000.0)
    # 18 m/s rather than a round 20 m/s: at 20 m/s and 35 000 lines/s the chord
    # 2R/|V| of several swept radii is a whole number of lines, where the
    # line-quantised initial guess is exact by coincidence.
    return Scene(camera=cam, radius_m=0.0335, speed_mps=18.0, z_m=3.0, y_m=0.1, direction_deg=0.0)


def fig5_config(trials: int = 16, seed: int = 0, textures: Sequence[str] = TEXTURES, methods: Sequence[str] = DEFAULT_METHODS, points: int = 5) -> ExperimentConfig:
    """The synthetic sweeps of the paper's Fig. 5 (Sec. 3.A).

    Base: tennis ball (R = 33.5 mm) at 18 m/s perpendicular to the viewing
    plane, 3 m from a 2048-px camera (f = 4000 px) at 35 000 lines/s, centre
    0.1 m off the optical axis along the sensor.  Sweeps (``points`` values
    each, log- or linearly spaced):

    - radius 0.02 m (table tennis) to 0.11 m (football);
    - speed 2 m/s (a slow roll) to 60 m/s (a serve);
    - direction 0 deg (perpendicular) to 60 deg towards the sensor y;
    - line rate 2 000 to 140 000 lines/s.
    """
    sweeps = (
        Sweep("radius_m", _spaced(0.02, 0.11, points, log=True, digits=3)),
        Sweep("speed_mps", _spaced(2.0, 60.0, points, log=True, digits=2)),
        Sweep("direction_deg", _spaced(0.0, 60.0, points, log=False, digits=2)),
        Sweep("line_rate_hz", _spaced(2000.0, 140000.0, points, log=True, digits=2)),
    )
    return ExperimentConfig(
        name="fig5",
        scene=_fig5_scene(),
        sweeps=sweeps,
        trials=trials,
        seed=seed,
        textures=tuple(textures),
        methods=tuple(methods),
        description="Synthetic one-factor sweeps after Zhao & Wen, Fig. 5: ball size, speed, direction and line rate.",
        source="fig5",
    )


def fig8_config(trials: int = 16, seed: int = 0, textures: Sequence[str] = TEXTURES, methods: Sequence[str] = DEFAULT_METHODS) -> ExperimentConfig:
    """The laboratory cases of the paper's Fig. 7-8 (Sec. 3.B), simulated.

    A tennis ball (R = 33.5 mm) on a rail at a constant 0.09 m/s, 1 m from a
    BASLER spL2048-70km-like camera (2048 px, f = 2300 px, exposure 2 ms;
    the ``paper-rail`` preset).  Rotating the viewing plane about the optical
    axis by 0, 4 and 10 deg gives the rail motion a component along the
    sensor (``direction_deg``; at 200 lines/s); the scan rate is 100 or 200
    lines/s (at 0 deg).
    """
    from .presets import get_preset

    p = get_preset("paper-rail")
    m = p.motion
    scene = Scene(
        camera=p.camera,
        radius_m=m.radius_m,
        # 0.09 m/s rather than the preset's 0.1 m/s: at 0.1 m/s the chord
        # 2R/|V| is exactly 134 (67) lines at 200 (100) lines/s, where the
        # line-quantised initial guess is exact by coincidence.
        speed_mps=0.09,
        z_m=m.position_m[2],
        y_m=m.position_m[1],
        ball_level=0.65,
        background_level=0.1,
    )
    return ExperimentConfig(
        name="fig8",
        scene=scene,
        sweeps=(Sweep("direction_deg", (0.0, 4.0, 10.0)), Sweep("line_rate_hz", (100.0, 200.0))),
        trials=trials,
        seed=seed,
        textures=tuple(textures),
        methods=tuple(methods),
        description="The paper's laboratory rail (Sec. 3.B, Fig. 7-8), simulated: viewing-plane rotation 0/4/10 deg and 100/200 lines/s.",
        source="fig8",
    )


def quick_config(cfg: ExperimentConfig, trials: int = 8, methods: Sequence[str] | None = None) -> ExperimentConfig:
    """The ``--quick`` version: the end points of every sweep and ``trials`` trials.

    Parameters
    ----------
    methods : sequence of str, optional
        Methods to keep (default: all of ``cfg``'s).
    """
    sweeps = tuple(Sweep(s.factor, (min(s.values), max(s.values)) if len(s.values) > 1 else s.values) for s in cfg.sweeps)
    return replace(cfg, sweeps=sweeps, trials=trials, methods=tuple(methods) if methods else cfg.methods)


def fig5_quick_config(seed: int = 0, textures: Sequence[str] = ("none",), methods: Sequence[str] = ("initial", "fit")) -> ExperimentConfig:
    """``fig5 --quick``: the end points of each factor, 8 trials, untextured.

    By default the paper's Powell refinement (0.3-4 s per ball, about 10x
    the fit) and the textured ball are left out and the slowest corners are
    moved in (speed 4.7 m/s, 5 800 lines/s, both values of the full sweep)
    so that the run takes about half a minute on 2 cores.
    """
    full = fig5_config(trials=8, seed=seed, textures=textures, methods=methods)
    sweeps = (
        Sweep("radius_m", (0.02, 0.11)),
        Sweep("speed_mps", (4.7, 60.0)),
        Sweep("direction_deg", (0.0, 60.0)),
        Sweep("line_rate_hz", (5800.0, 140000.0)),
    )
    return replace(full, sweeps=sweeps, name="fig5-quick")


def replace_trials(cfg: ExperimentConfig, trials: int) -> ExperimentConfig:
    """``cfg`` with another number of trials per point (validated)."""
    return replace(cfg, trials=trials)


def _spaced(lo: float, hi: float, n: int, log: bool, digits: int) -> tuple[float, ...]:
    if n < 2:
        return (lo,)
    xs = np.geomspace(lo, hi, n) if log else np.linspace(lo, hi, n)
    return tuple(float(f"{x:.{digits}g}") for x in xs)


# --------------------------------------------------------------------------- TOML configs
_TOP_KEYS = {"name", "description", "trials", "seed", "textures", "methods", "bound", "camera", "ball", "noise", "sweep"}
_BALL_KEYS = {"radius_m", "speed_mps", "direction_deg", "direction_z_deg", "y_m", "z_m", "ball_level", "background_level", "shading"}
_NOISE_KEYS = {f.name for f in fields(SensorNoise)}
_SWEEP_KEYS = {"factor", "values", "start", "stop", "num", "log"}


def load_config(path: str | Path) -> ExperimentConfig:
    """Read a custom experiment from TOML (see ``examples/custom_experiment.toml``).

    Every key is checked before any work; errors name the file and the key.

    Raises
    ------
    ExperimentConfigError
    """
    path = Path(path)
    src = str(path)
    try:
        raw = tomllib.loads(path.read_text())
    except FileNotFoundError:
        raise ExperimentConfigError(src, None, "no such file") from None
    except (OSError, UnicodeDecodeError) as exc:
        raise ExperimentConfigError(src, None, f"cannot read ({exc})") from None
    except tomllib.TOMLDecodeError as exc:
        raise ExperimentConfigError(src, None, f"not valid TOML ({exc})") from None
    return config_from_dict(raw, src, base_dir=path.parent)


def config_from_dict(raw: dict[str, Any], src: str = "<config>", base_dir: Path | None = None) -> ExperimentConfig:
    """Build a config from the TOML structure (see :func:`load_config`)."""

    def bad(key: str | None, problem: str) -> ExperimentConfigError:
        return ExperimentConfigError(src, key, problem)

    def table(d: dict, name: str, allowed: set[str]) -> dict:
        t = d.get(name, {})
        if not isinstance(t, dict):
            raise bad(name, "must be a table")
        unknown = sorted(set(t) - allowed)
        if unknown:
            raise bad(f"{name}.{unknown[0]}", f"unknown key (allowed: {', '.join(sorted(allowed))})")
        return t

    unknown = sorted(set(raw) - _TOP_KEYS)
    if unknown:
        raise bad(unknown[0], f"unknown key (allowed: {', '.join(sorted(_TOP_KEYS))})")
    # camera: inline table or path to a camera TOML (relative to this file)
    if "camera" not in raw:
        raise bad("camera", "missing (an inline [camera] table or a path to a camera TOML)")
    cam_raw = raw["camera"]
    try:
        if isinstance(cam_raw, str):
            p = Path(cam_raw)
            if not p.is_absolute() and base_dir is not None:
                p = base_dir / p
            camera = load_camera(p)
        elif isinstance(cam_raw, dict):
            camera = camera_from_dict(cam_raw, f"{src} [camera]")
        else:
            raise bad("camera", "must be a table or a path string")
    except ExperimentConfigError:
        raise
    except (BallscanError, ValueError) as exc:
        raise bad("camera", str(exc)) from None

    ball = table(raw, "ball", _BALL_KEYS)
    for k in ("radius_m", "speed_mps", "z_m"):
        if k not in ball:
            raise bad(f"ball.{k}", "missing")
    kw: dict[str, Any] = {}
    for k, v in ball.items():
        if k == "shading":
            if not isinstance(v, bool):
                raise bad("ball.shading", f"must be true or false, got {v!r}")
            kw[k] = v
        else:
            kw[k] = _num(v, f"ball.{k}", bad)
    noise_kw = table(raw, "noise", _NOISE_KEYS)
    try:
        noise = SensorNoise(**noise_kw)
    except (TypeError, ValueError) as exc:
        raise bad("noise", str(exc)) from None
    scene = Scene(camera=camera, noise=noise, **kw)
    _check_scene(scene, src, "ball")

    sw_raw = raw.get("sweep")
    if not isinstance(sw_raw, list) or not sw_raw:
        raise bad("sweep", "at least one [[sweep]] table with factor and values (or start, stop, num) is needed")
    sweeps = []
    for k, s in enumerate(sw_raw):
        key = f"sweep[{k}]"
        if not isinstance(s, dict):
            raise bad(key, "must be a table")
        unknown = sorted(set(s) - _SWEEP_KEYS)
        if unknown:
            raise bad(f"{key}.{unknown[0]}", f"unknown key (allowed: {', '.join(sorted(_SWEEP_KEYS))})")
        if "factor" not in s:
            raise bad(f"{key}.factor", "missing")
        if s["factor"] not in FACTORS:
            raise bad(f"{key}.factor", f"unknown factor {s['factor']!r}; choose one of {', '.join(FACTORS)}")
        if "values" in s:
            if any(x in s for x in ("start", "stop", "num", "log")):
                raise bad(key, "give either values or start/stop/num, not both")
            if not isinstance(s["values"], list):
                raise bad(f"{key}.values", "must be a list of numbers")
            if not s["values"]:
                raise bad(f"{key}.values", "empty range")
            vals = tuple(_num(v, f"{key}.values", bad) for v in s["values"])
        else:
            for x in ("start", "stop", "num"):
                if x not in s:
                    raise bad(f"{key}.{x}", "missing (or give values = [...])")
            num = s["num"]
            if isinstance(num, bool) or not isinstance(num, int) or num < 1:
                raise bad(f"{key}.num", f"must be a positive integer (empty range otherwise), got {num!r}")
            a, b = _num(s["start"], f"{key}.start", bad), _num(s["stop"], f"{key}.stop", bad)
            log = s.get("log", False)
            if not isinstance(log, bool):
                raise bad(f"{key}.log", f"must be true or false, got {log!r}")
            if log and not (a > 0 and b > 0):
                raise bad(f"{key}.start", "a log range needs positive start and stop")
            xs = np.geomspace(a, b, num) if log else np.linspace(a, b, num)
            vals = tuple(float(f"{x:.6g}") for x in xs)
        sweeps.append(Sweep(s["factor"], vals))

    def opt(key: str, default, kind):
        v = raw.get(key, default)
        if kind is int and (isinstance(v, bool) or not isinstance(v, int)):
            raise bad(key, f"must be an integer, got {v!r}")
        if kind is bool and not isinstance(v, bool):
            raise bad(key, f"must be true or false, got {v!r}")
        if kind is str and not isinstance(v, str):
            raise bad(key, f"must be a string, got {v!r}")
        if kind is list and not (isinstance(v, (list, tuple)) and all(isinstance(x, str) for x in v)):
            raise bad(key, f"must be a list of strings, got {v!r}")
        return v

    name = opt("name", Path(src).stem, str)
    if not name or any(c in name for c in "/\\"):
        raise bad("name", f"must be a non-empty file-name-safe string, got {name!r}")
    return ExperimentConfig(
        name=name,
        scene=scene,
        sweeps=tuple(sweeps),
        trials=opt("trials", 16, int),
        seed=opt("seed", 0, int),
        textures=tuple(opt("textures", list(TEXTURES), list)),
        methods=tuple(opt("methods", list(DEFAULT_METHODS), list)),
        bound=opt("bound", True, bool),
        description=opt("description", "", str),
        source=src,
    )


def _num(v: Any, key: str, bad) -> float:
    if isinstance(v, bool) or not isinstance(v, (int, float)):
        raise bad(key, f"must be a number, got {v!r}")
    if not math.isfinite(v):
        raise bad(key, f"must be finite, got {v!r}")
    return float(v)
