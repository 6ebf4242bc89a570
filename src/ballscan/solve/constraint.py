"""Known constraints on the ball's world motion, as priors of the joint fit.

A constraint replaces (or adds to) a second camera: it enters the fit of
:mod:`ballscan.solve.joint` as whitened residuals of the world state
``(P, V)`` (the centre at ``t_ref`` and the velocity, Eq. (8) in the world
frame) with its own sigma.

``plane``
    The ball rolls on a known plane ``n . X = d`` (the paper's laboratory
    rail): its centre stays ``R`` from it on the side ``n`` points to
    (``n . C = d + R``, sigma ``sigma_m``) and its velocity lies in it
    (``n . V / |V| = 0``, sigma ``sin(sigma_deg)``).
``point``
    The ball passes through a known point ``Q`` (a tee, a release zone)
    within ``sigma_m``: the trajectory's offset from ``Q`` at its closest
    approach, across the velocity, is 0.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

__all__ = ["Constraint", "parse_constraint"]

_KINDS = ("plane", "point")


@dataclass(frozen=True)
class Constraint:
    """A known plane or point of the ball's world motion.

    Attributes
    ----------
    kind : {"plane", "point"}
    normal : tuple of 3 floats
        Plane: unit normal (world frame), pointing to the ball's side.
    offset_m : float
        Plane: ``d`` of ``n . X = d`` (m).
    point_m : tuple of 3 floats
        Point: ``Q`` (world frame, m).
    sigma_m : float
        1-sigma of the centre's distance to the plane (less ``R``), or of its
        closest approach to ``Q`` (m).
    sigma_deg : float
        Plane: 1-sigma of the velocity's angle to the plane (degrees).
    """

    kind: str
    normal: tuple[float, float, float] = (0.0, 0.0, 1.0)
    offset_m: float = 0.0
    point_m: tuple[float, float, float] = (0.0, 0.0, 0.0)
    sigma_m: float = 1e-3
    sigma_deg: float = 0.5

    def __post_init__(self) -> None:
        if self.kind not in _KINDS:
            raise ValueError(f"constraint: kind must be one of {', '.join(_KINDS)}, got {self.kind!r}")
        n = np.asarray(self.normal, dtype=float)
        if n.shape != (3,) or not np.all(np.isfinite(n)) or np.linalg.norm(n) == 0:
            raise ValueError(f"constraint: the plane's normal must be 3 finite numbers, not all 0, got {self.normal!r}")
        object.__setattr__(self, "normal", tuple(float(v) for v in n / np.linalg.norm(n)))
        q = np.asarray(self.point_m, dtype=float)
        if q.shape != (3,) or not np.all(np.isfinite(q)):
            raise ValueError(f"constraint: the point must be 3 finite numbers, got {self.point_m!r}")
        object.__setattr__(self, "point_m", tuple(float(v) for v in q))
        if not (math.isfinite(self.offset_m)):
            raise ValueError(f"constraint: the plane's offset must be finite, got {self.offset_m!r}")
        if not (math.isfinite(self.sigma_m) and self.sigma_m > 0):
            raise ValueError(f"constraint: sigma_m must be positive, got {self.sigma_m!r}")
        if not (math.isfinite(self.sigma_deg) and 0 < self.sigma_deg < 90):
            raise ValueError(f"constraint: sigma_deg must be in (0, 90), got {self.sigma_deg!r}")

    @property
    def n_residuals(self) -> int:
        return 2 if self.kind == "plane" else 3

    def residuals(self, state: np.ndarray, radius_m: float, gravity_mps2: np.ndarray) -> np.ndarray:
        """Whitened residuals of the world state ``(P, V)`` (m, m/s) at the fit's reference time."""
        P, V = state[:3], state[3:6]
        if self.kind == "plane":
            n = np.asarray(self.normal)
            speed = max(float(np.linalg.norm(V)), 1e-12)
            return np.array([(n @ P - self.offset_m - radius_m) / self.sigma_m, (n @ V / speed) / math.sin(math.radians(self.sigma_deg))])
        Q = np.asarray(self.point_m)
        g = np.asarray(gravity_mps2, dtype=float)
        # closest approach of the (accelerated) path to Q: Newton on d/dtau |X(tau) - Q|^2 from the straight line's
        vv = max(float(V @ V), 1e-24)
        tau = float((Q - P) @ V) / vv
        for _ in range(3):
            X = P + V * tau + 0.5 * g * tau * tau
            v = V + g * tau
            f = float((X - Q) @ v)
            df = float(v @ v + (X - Q) @ g)
            if df <= 0:
                break
            tau -= f / df
        X = P + V * tau + 0.5 * g * tau * tau
        v = V + g * tau
        u = v / max(float(np.linalg.norm(v)), 1e-12)
        d = (X - Q) - ((X - Q) @ u) * u
        return d / self.sigma_m

    def jacobian(self, state: np.ndarray, radius_m: float, gravity_mps2: np.ndarray) -> np.ndarray:
        """``d residuals / d (P, V)`` (k, 6), by central differences (the residuals are smooth and cheap)."""
        x = np.asarray(state, dtype=float)
        J = np.zeros((self.n_residuals, 6))
        for i in range(6):
            h = 1e-6 * max(abs(x[i]), 1.0)
            xp, xm = x.copy(), x.copy()
            xp[i] += h
            xm[i] -= h
            J[:, i] = (self.residuals(xp, radius_m, gravity_mps2) - self.residuals(xm, radius_m, gravity_mps2)) / (2 * h)
        return J

    def describe(self) -> dict:
        """The constraint as reported in results (JSON-ready)."""
        if self.kind == "plane":
            return {"kind": "plane", "normal": list(self.normal), "offset_m": self.offset_m, "sigma_m": self.sigma_m, "sigma_deg": self.sigma_deg}
        return {"kind": "point", "point_m": list(self.point_m), "sigma_m": self.sigma_m}


def _numbers(text: str, spec: str) -> list[float]:
    try:
        return [float(v) for v in text.split(",")] if text else []
    except ValueError:
        raise ValueError(f"--constraint: not numbers in {spec!r}") from None


def parse_constraint(spec: str) -> Constraint:
    """Parse ``plane:NX,NY,NZ,D[,SIGMA_M[,SIGMA_DEG]]`` or ``point:X,Y,Z[,SIGMA_M]`` (world frame, metres, degrees).

    Defaults: ``SIGMA_M`` 1 mm for a plane and 10 mm for a point, ``SIGMA_DEG`` 0.5 degrees.
    """
    kind, _, rest = spec.partition(":")
    vals = _numbers(rest, spec)
    if kind == "plane":
        if len(vals) not in (4, 5, 6):
            raise ValueError(f"--constraint: expected 'plane:NX,NY,NZ,D[,SIGMA_M[,SIGMA_DEG]]', got {spec!r}")
        kw = {"sigma_m": vals[4]} if len(vals) > 4 else {}
        if len(vals) > 5:
            kw["sigma_deg"] = vals[5]
        return Constraint("plane", normal=tuple(vals[:3]), offset_m=vals[3], **kw)
    if kind == "point":
        if len(vals) not in (3, 4):
            raise ValueError(f"--constraint: expected 'point:X,Y,Z[,SIGMA_M]', got {spec!r}")
        return Constraint("point", point_m=tuple(vals[:3]), sigma_m=vals[3] if len(vals) > 3 else 0.01)
    raise ValueError(f"--constraint: expected 'plane:...' or 'point:...', got {spec!r}")
