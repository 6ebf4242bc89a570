"""Estimates and their serialisation (geometry.md "Ground truth and result files").

An estimate that cannot be made is still a value: its ``undetermined`` names
the keys the image does not determine, those keys are ``None`` (JSON
``null``) and ``flags`` says why, never a guessed number.
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from ..geometry.camera import LineScanCamera
from ..geometry.motion import BallMotion
from ..solve.derived import COVARIANCE_PARAMETERS, WORLD_COVARIANCE_PARAMETERS, Derived, Transverse, derive, derive_transverse

if TYPE_CHECKING:
    from ..measure.edges import EdgeMeasurements
    from ..measure.shading import LimbProfile
    from .recipe import Recipe
    from .stages import StageRecord

__all__ = ["BallEstimate", "EstimateReport", "FLAGS", "jsonable"]

#: The flag vocabulary of geometry.md.
FLAGS = (
    "cut_first_line",
    "cut_last_line",
    "cut_sensor_end",
    "overlap",
    "saturated",
    "dropped_lines",
    "initial_degenerate",
    "not_converged",
    "degenerate",
    "texture_at_limb",
    "both_signs",
    "defocus",
    "not_a_ball",
    "implausible_radius",
    "implausible_speed",
    "implausible_range",
    "wrong_bit_depth",
)


def _tuple3(v) -> tuple[float, float, float] | None:
    if v is None:
        return None
    a = np.asarray(v, dtype=float).reshape(3)
    return (float(a[0]), float(a[1]), float(a[2]))


@dataclass(frozen=True)
class BallEstimate:
    """One ball's estimated motion in the camera frame.

    Attributes
    ----------
    method : str
        ``"paper"`` or ``"fit"``.
    radius_m : float
        The known radius used.
    t_c_s, position_m, velocity_mps, speed_mps
        The estimate (seconds, metres, m/s); ``None`` where undetermined.
    t_c_sigma_s, position_sigma_m, velocity_sigma_mps, speed_sigma_mps
        1-sigma uncertainties where the method provides them.
    transverse : Transverse or None
        Where the velocity is undetermined only through its component along
        the camera's line of sight (one camera's weak axis): the velocity
        across it, what the image does determine
        (:class:`ballscan.solve.derived.Transverse`); None otherwise (the
        velocity is whole, or undetermined across the line of sight too).
    initial : BallEstimate or None
        The key-point initial guess (paper Eq. (3)-(7)).
    flags : tuple of str
        Words of :data:`FLAGS`.
    undetermined : tuple of str
        Keys the image cannot determine.
    first_line, last_line : int
        Lines of the image the ball was measured on.
    run_time_s : float
        Seconds spent on this ball.
    extra : dict
        Method-specific diagnostics (energy, evaluations, chi-square ...).
    record : StageRecord or None
        Which path the fit's stages took (:class:`ballscan.pipeline.stages.StageRecord`);
        not part of the JSON output (``extra`` repeats it there).
    covariance : ndarray (6, 6) or None
        Of the fitted parameters in the order of
        :data:`ballscan.solve.derived.COVARIANCE_PARAMETERS` (``t_c``, ``y0``,
        ``z0``, ``vx``, ``vy``, ``vz``; seconds, metres, m/s); NaN in the rows
        of undetermined parameters; None without uncertainties (the paper's
        method).
    fitted_edges : EdgeMeasurements or None
        The edges the reported fit used (a joint fit of several cameras
        fits them again, :mod:`ballscan.pipeline.rig`); not part of the JSON
        output. None for the paper's method.
    pixel_limb : LimbProfile or None
        Where the reported fit took edges although the pixel model describes
        the ball: the limb model they were measured with (the joint fit
        fits their windows' pixels instead); not part of the JSON output.
    """

    method: str
    radius_m: float
    t_c_s: float | None
    position_m: tuple[float, float, float] | None
    velocity_mps: tuple[float, float, float] | None
    speed_mps: float | None = None
    t_c_sigma_s: float | None = None
    position_sigma_m: tuple[float, float, float] | None = None
    velocity_sigma_mps: tuple[float, float, float] | None = None
    speed_sigma_mps: float | None = None
    transverse: Transverse | None = None
    initial: "BallEstimate | None" = None
    flags: tuple[str, ...] = ()
    undetermined: tuple[str, ...] = ()
    first_line: int | None = None
    last_line: int | None = None
    run_time_s: float = 0.0
    extra: dict[str, Any] = field(default_factory=dict, compare=False)
    record: "StageRecord | None" = field(default=None, compare=False)
    covariance: np.ndarray | None = field(default=None, compare=False, repr=False)
    fitted_edges: "EdgeMeasurements | None" = field(default=None, compare=False, repr=False)
    pixel_limb: "LimbProfile | None" = field(default=None, compare=False, repr=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "position_m", _tuple3(self.position_m))
        object.__setattr__(self, "velocity_mps", _tuple3(self.velocity_mps))
        object.__setattr__(self, "position_sigma_m", _tuple3(self.position_sigma_m))
        object.__setattr__(self, "velocity_sigma_mps", _tuple3(self.velocity_sigma_mps))
        if self.transverse is not None and self.velocity_mps is not None:
            raise ValueError(f"transverse: the velocity across the line of sight of a velocity undetermined along it, got one beside velocity_mps {self.velocity_mps!r}")
        if self.speed_mps is None and self.velocity_mps is not None:
            object.__setattr__(self, "speed_mps", float(np.linalg.norm(self.velocity_mps)))
        unknown = set(self.flags) - set(FLAGS)
        if unknown:
            raise ValueError(f"flags: unknown words {sorted(unknown)} (geometry.md lists {FLAGS})")
        # keep flags unique and in vocabulary order
        object.__setattr__(self, "flags", tuple(f for f in FLAGS if f in self.flags))

    @classmethod
    def from_motion(cls, motion: BallMotion, method: str, **kw: Any) -> "BallEstimate":
        return cls(
            method=method,
            radius_m=motion.radius_m,
            t_c_s=motion.t_c_s,
            position_m=motion.position_m,
            velocity_mps=motion.velocity_mps,
            **kw,
        )

    @classmethod
    def undetermined_estimate(cls, method: str, radius_m: float, reason: str, flags: tuple[str, ...] = (), **kw: Any) -> "BallEstimate":
        """An estimate the image cannot give: every motion key ``None``, flagged ``degenerate``.

        ``reason`` (one line) is kept in ``extra["reason"]``.
        """
        return cls(
            method=method,
            radius_m=radius_m,
            t_c_s=None,
            position_m=None,
            velocity_mps=None,
            speed_mps=None,
            flags=tuple(flags) + ("degenerate",),
            undetermined=("t_c_s", "position_m", "velocity_mps", "speed_mps"),
            extra={"reason": " ".join(reason.split())},
            **kw,
        )

    def motion(self) -> BallMotion | None:
        """The estimate as a :class:`BallMotion` (None when undetermined)."""
        if self.t_c_s is None or self.position_m is None or self.velocity_mps is None:
            return None
        return BallMotion(self.radius_m, self.t_c_s, self.position_m, self.velocity_mps)

    def derived(self, camera: LineScanCamera | None = None) -> Derived | None:
        """Transverse speed, direction angles, the world frame and their sigmas (:func:`ballscan.solve.derived.derive`).

        Where only the velocity along the line of sight is undetermined, the
        part across it (:func:`ballscan.solve.derived.derive_transverse`);
        None when the velocity is undetermined otherwise.
        """
        if self.position_m is not None and self.velocity_mps is not None:
            return derive(camera, self.position_m, self.velocity_mps, self.covariance)
        if self.transverse is not None:
            return derive_transverse(self.transverse)
        return None

    # ---------------------------------------------------------- serialisation
    def to_dict(self, camera: LineScanCamera | None = None) -> dict[str, Any]:
        """geometry.md estimate keys (plus diagnostics), JSON-ready."""
        d: dict[str, Any] = {
            "method": self.method,
            "radius_m": self.radius_m,
            "t_c_s": self.t_c_s,
            "position_m": self.position_m,
            "velocity_mps": self.velocity_mps,
            "speed_mps": self.speed_mps,
        }
        if self.t_c_sigma_s is not None:
            d["t_c_sigma_s"] = self.t_c_sigma_s
        if self.position_sigma_m is not None:
            d["position_sigma_m"] = self.position_sigma_m
        if self.velocity_sigma_mps is not None:
            d["velocity_sigma_mps"] = self.velocity_sigma_mps
        if self.speed_sigma_mps is not None:
            d["speed_sigma_mps"] = self.speed_sigma_mps
        if self.covariance is not None:
            d["covariance"] = {"parameters": list(COVARIANCE_PARAMETERS), "matrix": np.asarray(self.covariance, dtype=float)}
        der = self.derived(camera)
        if self.transverse is not None:
            t = self.transverse
            d["velocity_transverse_mps"] = list(t.velocity_mps)
            d["transverse_axis"] = list(t.axis)
            d["velocity_transverse_cov_m2ps2"] = t.covariance
            d["transverse_fit"] = t.source
        if der is not None:
            d["speed_transverse_mps"] = der.speed_transverse_mps
            if self.covariance is not None:
                d["speed_transverse_sigma_mps"] = der.speed_transverse_sigma_mps
                d["direction_deg"] = der.direction_deg
                d["direction_sigma_deg"] = der.direction_sigma_deg
                d["speed_direction_correlation"] = der.speed_direction_correlation
        d["flags"] = list(self.flags)
        d["undetermined"] = list(self.undetermined)
        d["first_line"] = self.first_line
        d["last_line"] = self.last_line
        d["run_time_s"] = self.run_time_s
        if camera is not None and camera.has_pose:
            d["world"] = self._world(der)
        if self.initial is not None:
            d["initial"] = self.initial.to_dict(camera)
        for k, v in self.extra.items():
            d.setdefault(k, v)
        # NaN (a sigma of a parameter the fit could not determine) is not JSON: null
        return jsonable(d)

    def _world(self, der: Derived | None) -> dict[str, Any]:
        """The ``"world"`` object from :meth:`derived` of a camera with a pose (None: the motion is undetermined)."""
        if der is not None and der.world_velocity_mps is None:
            der = None  # vx and vy alone: no world velocity without vz
        w: dict[str, Any] = {
            "position_m": None if der is None else der.world_position_m,
            "velocity_mps": None if der is None else der.world_velocity_mps,
            "speed_mps": self.speed_mps,
        }
        if der is None:
            return w
        w["elevation_deg"] = der.elevation_deg
        w["azimuth_deg"] = der.azimuth_deg
        if self.covariance is not None:
            w["position_sigma_m"] = der.world_position_sigma_m
            w["velocity_sigma_mps"] = der.world_velocity_sigma_mps
            w["speed_sigma_mps"] = self.speed_sigma_mps
            w["elevation_sigma_deg"] = der.elevation_sigma_deg
            w["azimuth_sigma_deg"] = der.azimuth_sigma_deg
            w["covariance"] = {"parameters": list(WORLD_COVARIANCE_PARAMETERS), "matrix": der.world_covariance}
        return w


@dataclass(frozen=True)
class EstimateReport:
    """All balls of one image, in the order of ``t_c_s``, and the :class:`~ballscan.pipeline.recipe.Recipe` that measured them."""

    image: str
    balls: tuple[BallEstimate, ...]
    recipe: "Recipe | None" = None

    def to_dict(self, camera: LineScanCamera | None = None) -> dict[str, Any]:
        """geometry.md's result: the image, the package's version and the recipe's changes from the default (what made it), the balls."""
        from .. import __version__

        d: dict[str, Any] = {"image": self.image, "ballscan_version": __version__}
        if self.recipe is not None:
            d["recipe"] = self.recipe.changes()
        d["balls"] = [b.to_dict(camera) for b in self.balls]
        return d

    def to_json(self, camera: LineScanCamera | None = None) -> str:
        return json.dumps(self.to_dict(camera), indent=2, allow_nan=False)


def jsonable(v: Any) -> Any:
    """JSON-ready value: arrays to lists, numpy scalars to Python, NaN/inf to null (the results' and the rigs' JSON)."""
    if isinstance(v, np.ndarray):
        return jsonable(v.tolist())
    if isinstance(v, (np.floating, np.integer, np.bool_)):
        return jsonable(v.item())
    if isinstance(v, float) and not math.isfinite(v):
        return None
    if isinstance(v, dict):
        return {k: jsonable(x) for k, x in v.items()}
    if isinstance(v, (list, tuple)):
        return [jsonable(x) for x in v]
    return v
