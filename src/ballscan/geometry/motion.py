"""Ball motion model: the dynamic sphere of the paper's first Eq. (8).

The centre moves as ``C(t) = C0 + V (t - t_c) + a (t - t_c)^2 / 2`` with
``C0 = (0, y0, z0)``: ``t_c`` is the moment the centre crosses the viewing
plane ``x = 0`` (camera frame of geometry.md, metres and seconds).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

__all__ = ["BallMotion", "PARAM_NAMES"]

#: Order of the six motion parameters used by every estimator (paper Sec. 2.C).
PARAM_NAMES = ("t_c_s", "y0_m", "z0_m", "vx_mps", "vy_mps", "vz_mps")


def _vec3(value, name: str) -> tuple[float, float, float]:
    arr = np.asarray(value, dtype=float).reshape(-1)
    if arr.shape != (3,):
        raise ValueError(f"{name}: expected 3 values, got {arr.size}")
    if not np.all(np.isfinite(arr)):
        raise ValueError(f"{name}: values must be finite, got {arr.tolist()}")
    return (float(arr[0]), float(arr[1]), float(arr[2]))


@dataclass(frozen=True)
class BallMotion:
    """A sphere of known radius in uniform (or uniformly accelerated) motion.

    Parameters
    ----------
    radius_m : float
        Ball radius ``R`` in metres.
    t_c_s : float
        Time at which the centre crosses the viewing plane, seconds.
    position_m : tuple of float
        Centre at ``t_c``, ``(0, y0, z0)`` in metres (its x must be 0).
    velocity_mps : tuple of float
        Velocity at ``t_c`` in m/s.
    acceleration_mps2 : tuple of float
        Known constant acceleration in the camera frame, m/s^2.
    """

    radius_m: float
    t_c_s: float
    position_m: tuple[float, float, float]
    velocity_mps: tuple[float, float, float]
    acceleration_mps2: tuple[float, float, float] = (0.0, 0.0, 0.0)

    def __post_init__(self) -> None:
        if not (math.isfinite(self.radius_m) and self.radius_m > 0):
            raise ValueError(f"radius_m: must be positive and finite, got {self.radius_m!r}")
        if not math.isfinite(self.t_c_s):
            raise ValueError(f"t_c_s: must be finite, got {self.t_c_s!r}")
        object.__setattr__(self, "position_m", _vec3(self.position_m, "position_m"))
        object.__setattr__(self, "velocity_mps", _vec3(self.velocity_mps, "velocity_mps"))
        object.__setattr__(self, "acceleration_mps2", _vec3(self.acceleration_mps2, "acceleration_mps2"))
        if abs(self.position_m[0]) > 1e-9:
            raise ValueError(
                f"position_m: x must be 0 (the centre at t_c lies in the viewing plane), got {self.position_m[0]!r}"
            )

    # ----------------------------------------------------------- parameters
    @classmethod
    def from_params(cls, theta: np.ndarray, radius_m: float, acceleration_mps2=(0.0, 0.0, 0.0)) -> "BallMotion":
        """Build from ``theta = (t_c, y0, z0, vx, vy, vz)`` (see :data:`PARAM_NAMES`)."""
        t = np.asarray(theta, dtype=float)
        return cls(radius_m, float(t[0]), (0.0, float(t[1]), float(t[2])), (float(t[3]), float(t[4]), float(t[5])), acceleration_mps2)

    def to_params(self) -> np.ndarray:
        """``(t_c, y0, z0, vx, vy, vz)`` as an array."""
        return np.array([self.t_c_s, self.position_m[1], self.position_m[2], *self.velocity_mps])

    # ------------------------------------------------------------- kinematics
    @property
    def speed_mps(self) -> float:
        return float(np.linalg.norm(self.velocity_mps))

    def centre(self, t_s: np.ndarray) -> np.ndarray:
        """Centre positions (..., 3) in metres at times ``t_s`` (seconds)."""
        dt = np.asarray(t_s, dtype=float)[..., None] - self.t_c_s
        c = np.asarray(self.position_m) + np.asarray(self.velocity_mps) * dt
        if any(self.acceleration_mps2):
            c = c + 0.5 * np.asarray(self.acceleration_mps2) * dt * dt
        return c

    def velocity_at(self, t_s: np.ndarray) -> np.ndarray:
        """Velocities (..., 3) in m/s at times ``t_s``."""
        dt = np.asarray(t_s, dtype=float)[..., None] - self.t_c_s
        return np.asarray(self.velocity_mps) + np.asarray(self.acceleration_mps2) * dt

    def to_dict(self) -> dict:
        """geometry.md truth keys."""
        d = {
            "radius_m": self.radius_m,
            "t_c_s": self.t_c_s,
            "position_m": list(self.position_m),
            "velocity_mps": list(self.velocity_mps),
            "speed_mps": self.speed_mps,
        }
        if any(self.acceleration_mps2):
            d["acceleration_mps2"] = list(self.acceleration_mps2)
        return d

    @classmethod
    def from_dict(cls, d: dict) -> "BallMotion":
        return cls(
            float(d["radius_m"]),
            float(d["t_c_s"]),
            tuple(d["position_m"]),
            tuple(d["velocity_mps"]),
            tuple(d.get("acceleration_mps2", (0.0, 0.0, 0.0))),
        )
