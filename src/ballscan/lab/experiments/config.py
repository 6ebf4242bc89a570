"""Experiment configurations: the base scene, the sweeps, their validation and TOML files.

An :class:`ExperimentConfig` is checked when it is built
(:func:`validate_config`): every value's range, and every sweep point's ball
imaged wholly inside the sensor in fewer than :data:`MAX_LINES` lines. Errors
are :class:`ExperimentConfigError`, one line naming the file and the key.
"""

from __future__ import annotations

import hashlib
import json
import math
import tomllib
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field, fields, replace
from functools import partial
from pathlib import Path
from typing import Any, Literal

import numpy as np

from ...errors import BallscanError, GeometryError
from ...geometry.camera import LineScanCamera, camera_from_dict, line_times, load_camera
from ...geometry.motion import BallMotion
from ...model.render import Appearance, SensorNoise

__all__ = [
    "ExperimentConfigError",
    "FACTORS",
    "METHODS",
    "DEFAULT_METHODS",
    "TEXTURES",
    "Method",
    "Texture",
    "MAX_LINES",
    "FactorSpec",
    "Scene",
    "Sweep",
    "ExperimentConfig",
    "validate_config",
    "TrialGeometry",
    "scene_geometry",
    "appearance",
    "crlb_noise_dn",
    "quick_config",
    "replace_trials",
    "load_config",
    "config_from_dict",
]

#: An estimator's name (see :data:`METHODS`).
Method = Literal["initial", "paper", "fit", "pixels"]
#: A ball surface's name (see :data:`TEXTURES`).
Texture = Literal["none", "tennis"]
#: Estimators that can be compared, in plotting order.
METHODS: tuple[Method, ...] = ("initial", "paper", "fit", "pixels")
#: Those an experiment compares unless told otherwise.
DEFAULT_METHODS: tuple[Method, ...] = ("initial", "paper", "fit")
#: Ball surfaces: flat albedo, or the tennis seam band of :class:`ballscan.model.render.Appearance`.
TEXTURES: tuple[Texture, ...] = ("none", "tennis")
#: Longest image a trial may render (lines); slower balls need a lower line rate.
MAX_LINES = 20000
#: Version of the trial format, part of :meth:`ExperimentConfig.fingerprint`.
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
    textures: tuple[Texture, ...] = TEXTURES
    methods: tuple[Method, ...] = DEFAULT_METHODS
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

    if not isinstance(cfg.name, str) or not cfg.name or any(c in cfg.name for c in "/\\"):
        raise bad("name", f"must be a non-empty file-name-safe string, got {cfg.name!r}")
    if not isinstance(cfg.bound, bool):
        raise bad("bound", f"must be true or false, got {cfg.bound!r}")
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
    from ...model.silhouette import silhouette

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
    from ...model.silhouette import visible_line_count

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


# --------------------------------------------------------------------------- derived configs
def quick_config(cfg: ExperimentConfig, trials: int = 8, methods: Sequence[str] | None = None) -> ExperimentConfig:
    """The ``--quick`` version: the end points of every sweep and ``trials`` trials.

    Parameters
    ----------
    methods : sequence of str, optional
        Methods to keep (default: all of ``cfg``'s).
    """
    sweeps = tuple(Sweep(s.factor, (min(s.values), max(s.values)) if len(s.values) > 1 else s.values) for s in cfg.sweeps)
    return replace(cfg, sweeps=sweeps, trials=trials, methods=tuple(methods) if methods else cfg.methods)


def replace_trials(cfg: ExperimentConfig, trials: int) -> ExperimentConfig:
    """``cfg`` with another number of trials per point (validated)."""
    return replace(cfg, trials=trials)


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
    """Build a config from the TOML structure (see :func:`load_config`).

    Parameters
    ----------
    raw : dict
        The parsed TOML: top-level keys, ``[camera]`` (a table or the path of
        a camera TOML), ``[ball]``, ``[noise]`` and ``[[sweep]]`` tables.
    src : str
        The file's name, in messages.
    base_dir : Path, optional
        Folder a relative camera path is taken from.

    Raises
    ------
    ExperimentConfigError
        Naming ``src`` and the first offending key.
    """
    bad = partial(ExperimentConfigError, src)
    _check_keys(raw, None, _TOP_KEYS, bad)
    camera = _camera_from(raw, src, base_dir, bad)
    scene = _scene_from(raw, camera, bad)
    _check_scene(scene, src, "ball")
    sweeps = _sweeps_from(raw.get("sweep"), bad)
    return ExperimentConfig(
        name=_option(raw, "name", Path(src).stem, str, bad),
        scene=scene,
        sweeps=sweeps,
        trials=_option(raw, "trials", 16, int, bad),
        seed=_option(raw, "seed", 0, int, bad),
        textures=tuple(_option(raw, "textures", list(TEXTURES), list, bad)),
        methods=tuple(_option(raw, "methods", list(DEFAULT_METHODS), list, bad)),
        bound=_option(raw, "bound", True, bool, bad),
        description=_option(raw, "description", "", str, bad),
        source=src,
    )


#: Builds the :class:`ExperimentConfigError` of one file from ``(key, problem)``.
_Bad = Callable[[str | None, str], ExperimentConfigError]


def _check_keys(table: dict, prefix: str | None, allowed: set[str], bad: _Bad) -> None:
    unknown = sorted(set(table) - allowed)
    if unknown:
        key = unknown[0] if prefix is None else f"{prefix}.{unknown[0]}"
        raise bad(key, f"unknown key (allowed: {', '.join(sorted(allowed))})")


def _table(raw: dict, name: str, allowed: set[str], bad: _Bad) -> dict:
    t = raw.get(name, {})
    if not isinstance(t, dict):
        raise bad(name, "must be a table")
    _check_keys(t, name, allowed, bad)
    return t


def _camera_from(raw: dict, src: str, base_dir: Path | None, bad: _Bad) -> LineScanCamera:
    """``camera``: an inline table or the path of a camera TOML (relative to the config's folder)."""
    if "camera" not in raw:
        raise bad("camera", "missing (an inline [camera] table or a path to a camera TOML)")
    cam_raw = raw["camera"]
    try:
        if isinstance(cam_raw, str):
            p = Path(cam_raw)
            if not p.is_absolute() and base_dir is not None:
                p = base_dir / p
            return load_camera(p)
        if isinstance(cam_raw, dict):
            return camera_from_dict(cam_raw, f"{src} [camera]")
        raise bad("camera", "must be a table or a path string")
    except ExperimentConfigError:
        raise
    except (BallscanError, ValueError) as exc:
        raise bad("camera", str(exc)) from None


def _scene_from(raw: dict, camera: LineScanCamera, bad: _Bad) -> Scene:
    """The base scene from ``[ball]`` and ``[noise]``."""
    ball = _table(raw, "ball", _BALL_KEYS, bad)
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
    noise_kw = _table(raw, "noise", _NOISE_KEYS, bad)
    try:
        noise = SensorNoise(**noise_kw)
    except (TypeError, ValueError) as exc:
        raise bad("noise", str(exc)) from None
    return Scene(camera=camera, noise=noise, **kw)


def _sweeps_from(sw_raw: Any, bad: _Bad) -> tuple[Sweep, ...]:
    """The ``[[sweep]]`` tables: a factor and ``values`` or ``start``/``stop``/``num`` (``log``)."""
    if not isinstance(sw_raw, list) or not sw_raw:
        raise bad("sweep", "at least one [[sweep]] table with factor and values (or start, stop, num) is needed")
    sweeps = []
    for k, s in enumerate(sw_raw):
        key = f"sweep[{k}]"
        if not isinstance(s, dict):
            raise bad(key, "must be a table")
        _check_keys(s, key, _SWEEP_KEYS, bad)
        if "factor" not in s:
            raise bad(f"{key}.factor", "missing")
        if s["factor"] not in FACTORS:
            raise bad(f"{key}.factor", f"unknown factor {s['factor']!r}; choose one of {', '.join(FACTORS)}")
        sweeps.append(Sweep(s["factor"], _sweep_values(s, key, bad)))
    return tuple(sweeps)


def _sweep_values(s: dict, key: str, bad: _Bad) -> tuple[float, ...]:
    if "values" in s:
        if any(x in s for x in ("start", "stop", "num", "log")):
            raise bad(key, "give either values or start/stop/num, not both")
        if not isinstance(s["values"], list):
            raise bad(f"{key}.values", "must be a list of numbers")
        if not s["values"]:
            raise bad(f"{key}.values", "empty range")
        return tuple(_num(v, f"{key}.values", bad) for v in s["values"])
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
    return tuple(float(f"{x:.6g}") for x in xs)


def _option(raw: dict, key: str, default: Any, kind: type, bad: _Bad) -> Any:
    """A top-level value of type ``kind`` (``list``: a list of strings), or ``default``."""
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


def _num(v: Any, key: str, bad: _Bad) -> float:
    if isinstance(v, bool) or not isinstance(v, (int, float)):
        raise bad(key, f"must be a number, got {v!r}")
    if not math.isfinite(v):
        raise bad(key, f"must be finite, got {v!r}")
    return float(v)
