"""The Cramér–Rao bound of a rig: every camera's information about the ball's world motion, summed (and a constraint's).

Camera ``k``'s bound (:func:`ballscan.solve.precision.edge_crlb` or
:func:`ballscan.solve.precision.pixel_crlb`, its nuisance parameters
marginalised) is the Fisher information ``F_k`` of its own parameters
``theta_k`` (Eq. (8) seen through its Eq. (1)); the world state's is
``sum_k G_k^T F_k G_k`` with ``G_k = d theta_k / d (P, V, offsets)``
(:func:`ballscan.geometry.rig.camera_params`), plus ``J_c^T J_c`` of a
constraint's whitened residuals.  Its inverse, carried to the reference
camera's crossing (:func:`ballscan.geometry.rig.world_crossing`), bounds
the world position, velocity, speed and direction of any unbiased joint
estimate.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable

import numpy as np

from ..geometry.camera import LineScanCamera
from ..geometry.motion import BallMotion
from ..geometry.rig import Rig, WorldMotion, camera_params, turned_camera, world_crossing
from ..model.silhouette import visible_line_count
from .constraint import Constraint
from .derived import WORLD_COVARIANCE_PARAMETERS, launch_angles
from .precision import edge_crlb

__all__ = ["RigBound", "direction_sigma_deg", "rig_crlb", "sweep_second_camera"]

CameraBound = Callable[[LineScanCamera, BallMotion], np.ndarray]


@dataclass(frozen=True)
class RigBound:
    """1-sigma Cramér–Rao bounds of a rig's joint estimate (world frame, the reference camera's crossing).

    Attributes
    ----------
    motion : WorldMotion
        Where the bound is evaluated (at the reference crossing).
    covariance : ndarray (7, 7)
        Of :data:`ballscan.solve.derived.WORLD_COVARIANCE_PARAMETERS`.
    clock_sigma_s : dict
        The unknown clocks' offsets' bounds by camera name (s).
    speed_sigma_mps : float
    elevation_sigma_deg, azimuth_sigma_deg : float
    direction_sigma_deg : float
        Largest principal sigma of the velocity's direction (degrees).
    per_camera : dict
        Each camera's own bound alone by name: the 6x6 covariance of its
        parameters (:data:`ballscan.geometry.motion.PARAM_NAMES`, its frame).
    """

    motion: WorldMotion
    covariance: np.ndarray
    clock_sigma_s: dict
    speed_sigma_mps: float
    elevation_sigma_deg: float
    azimuth_sigma_deg: float
    direction_sigma_deg: float
    per_camera: dict

    @property
    def sigmas(self) -> np.ndarray:
        return np.sqrt(np.abs(np.diag(self.covariance)))

    def to_dict(self) -> dict:
        s = self.sigmas
        return {
            "frame": "world",
            "motion": self.motion.to_dict(),
            "t_c_sigma_s": float(s[0]),
            "position_sigma_m": [float(v) for v in s[1:4]],
            "velocity_sigma_mps": [float(v) for v in s[4:7]],
            "speed_sigma_mps": self.speed_sigma_mps,
            "elevation_sigma_deg": self.elevation_sigma_deg,
            "azimuth_sigma_deg": self.azimuth_sigma_deg,
            "direction_sigma_deg": self.direction_sigma_deg,
            "clock_offset_sigma_s": dict(self.clock_sigma_s),
            "covariance": {"parameters": list(WORLD_COVARIANCE_PARAMETERS), "matrix": self.covariance.tolist()},
            "per_camera": {n: {"velocity_sigma_mps": [float(v) for v in np.sqrt(np.abs(np.diag(c)[3:]))]} for n, c in self.per_camera.items()},
        }

    def to_text(self) -> str:
        m, s = self.motion, self.sigmas
        lines = [f"joint Cramér–Rao bound (1-sigma), world frame, at t = {m.t_ref_s:.6g} s:"]
        for name, val, sig, unit in (
            ("t_c", m.t_ref_s, s[0], "s"),
            *((f"{a}", v, sg, "m") for a, v, sg in zip("xyz", m.position_m, s[1:4])),
            *((f"v{a}", v, sg, "m/s") for a, v, sg in zip("xyz", m.velocity_mps, s[4:7])),
            ("speed", m.speed_mps, self.speed_sigma_mps, "m/s"),
        ):
            lines.append(f"  {name:<10} {val:14.6g} {unit:<4} +- {sig:.3e}")
        lines.append(f"  elevation  +- {self.elevation_sigma_deg:.4f} deg   azimuth +- {self.azimuth_sigma_deg:.4f} deg   direction +- {self.direction_sigma_deg:.4f} deg")
        for n, v in self.clock_sigma_s.items():
            lines.append(f"  clock offset of {n} +- {v:.3e} s")
        for n, c in self.per_camera.items():
            sv = np.sqrt(np.abs(np.diag(c)[3:]))
            lines.append(f"  {n} alone: velocity sigma ({sv[0]:.3g}, {sv[1]:.3g}, {sv[2]:.3g}) m/s (its own frame)")
        return "\n".join(lines)


def direction_sigma_deg(velocity_mps: np.ndarray, cov_v: np.ndarray) -> float:
    """Largest principal 1-sigma of a velocity's direction (degrees): of its covariance across the velocity, over the speed."""
    V = np.asarray(velocity_mps, dtype=float)
    sp = float(np.linalg.norm(V))
    u = V / sp
    P = np.eye(3) - np.outer(u, u)
    lam = float(np.linalg.eigvalsh(P @ cov_v @ P).max())
    return math.degrees(math.sqrt(max(lam, 0.0)) / sp)


def _retimed(cm: BallMotion, camera: LineScanCamera) -> BallMotion:
    """The camera's view with the crossing early in an image that starts at line 0 (a bound does not depend on the time origin)."""
    t_c = (0.6 * visible_line_count(camera, cm) + 5.0) / camera.line_rate_hz
    return BallMotion(cm.radius_m, t_c, cm.position_m, cm.velocity_mps, cm.acceleration_mps2)


def rig_crlb(
    rig: Rig,
    motion: WorldMotion,
    camera_bound: CameraBound | None = None,
    *,
    edge_noise_px: float = 0.1,
    constraint: Constraint | None = None,
    retime: bool = True,
) -> RigBound:
    """The joint bound of a rig's cameras (and a constraint) on the world motion.

    Parameters
    ----------
    rig : Rig
    motion : WorldMotion
        World frame, rig clock; the bound is given at its crossing of the
        reference camera's plane.
    camera_bound : callable, optional
        ``(camera, camera_motion) -> covariance (6, 6)``: one camera's bound
        on its own parameters (nuisance parameters marginalised), e.g. a
        :class:`ballscan.solve.precision.PrecisionBound`'s ``covariance``;
        by default :func:`ballscan.solve.precision.edge_crlb`'s with ``edge_noise_px``.
    edge_noise_px : float
        1-sigma of one edge, pixels (the default bound's).
    constraint : Constraint, optional
    retime : bool
        Hand each camera's view to ``camera_bound`` with its crossing early
        in an image starting at line 0 (the bounds of
        :mod:`ballscan.solve.precision` assume one); False: in its own clock.

    Raises
    ------
    ValueError
        If the ball does not cross a camera's viewing plane in front of it.
    """
    if camera_bound is None:
        def camera_bound(cam, cm):
            return edge_crlb(cam, cm, edge_noise_px).covariance
    g = np.asarray(motion.gravity_mps2, dtype=float)
    unknown = rig.unknown_clocks
    n = 6 + len(unknown)
    F = np.zeros((n, n))
    per = {}
    for k, rc in enumerate(rig.cameras):
        off = rc.clock_offset_s if rc.clock_known else 0.0
        cm = motion.in_camera(rc, off)
        if cm is None or cm.position_m[2] <= motion.radius_m:
            raise ValueError(f"precision --rig: the ball does not cross camera {rc.name!r}'s viewing plane in front of it")
        ck = np.asarray(camera_bound(rc.camera, _retimed(cm, rc.camera) if retime else cm), dtype=float)
        per[rc.name] = ck
        d = np.sqrt(np.where(np.diag(ck) > 0, np.diag(ck), 1.0))
        Fk = np.linalg.pinv(ck / np.outer(d, d), hermitian=True) / np.outer(d, d)
        _, Jt, _ = camera_params(motion.state, rc.camera, motion.t_ref_s, g, off)
        G = np.zeros((6, n))
        G[:, :6] = Jt
        if k in unknown:
            G[0, 6 + unknown.index(k)] = 1.0
        F += G.T @ Fk @ G
    if constraint is not None:
        Jc = np.zeros((constraint.n_residuals, n))
        Jc[:, :6] = constraint.jacobian(motion.state, motion.radius_m, g)
        F += Jc.T @ Jc
    d = np.sqrt(np.where(np.diag(F) > 0, np.diag(F), 1.0))
    Fn = F / np.outer(d, d)
    w = np.linalg.eigvalsh(Fn)
    cov = np.full_like(F, np.inf) if w.min() <= 1e-12 * w.max() else np.linalg.inv(Fn) / np.outer(d, d)
    ref = rig.reference
    t, X, V, Jw, _ = world_crossing(motion.state, rig.cameras[ref].camera, motion.t_ref_s, g)
    cov7 = Jw @ cov[:6, :6] @ Jw.T if np.all(np.isfinite(cov)) else np.full((7, 7), np.inf)
    at = WorldMotion(motion.radius_m, t, tuple(X), tuple(V), tuple(g))
    Cv = cov7[4:, 4:]
    if np.all(np.isfinite(Cv)):
        u = V / np.linalg.norm(V)
        _, el_s, _, az_s = launch_angles(V, Cv)
        sp_s, dir_s = float(math.sqrt(max(u @ Cv @ u, 0.0))), direction_sigma_deg(V, Cv)
    else:
        el_s = az_s = sp_s = dir_s = math.inf
    clocks = {rig.cameras[k].name: float(math.sqrt(abs(cov[6 + i, 6 + i]))) for i, k in enumerate(unknown)}
    return RigBound(at, cov7, clocks, sp_s, el_s, az_s, dir_s, per)


def sweep_second_camera(
    rig: Rig, motion: WorldMotion, angles_deg, camera_bound: CameraBound | None = None, *, edge_noise_px: float = 0.1, constraint: Constraint | None = None
) -> list[tuple[float, RigBound]]:
    """The joint bound with the second camera replaced by the first turned ``angle`` degrees about the ball's path.

    The turn is about the line through the ball's crossing of the first
    camera's plane along that plane's normal (:func:`ballscan.geometry.rig.turned_camera`),
    so the second camera keeps the first one's distance and optics.
    """
    if len(rig.cameras) < 2:
        raise ValueError("precision --sweep: the rig needs a second camera to turn")
    first = rig.cameras[rig.reference]
    k2 = next(k for k in range(len(rig.cameras)) if k != rig.reference)
    g = np.asarray(motion.gravity_mps2, dtype=float)
    _, X, _, _, _ = world_crossing(motion.state, first.camera, motion.t_ref_s, g)
    out = []
    for a in angles_deg:
        cam = turned_camera(first.camera, X, float(a))
        r = rig.with_camera(k2, type(rig.cameras[k2])(rig.cameras[k2].name, cam, rig.cameras[k2].clock_offset_s, rig.cameras[k2].clock_sigma_s))
        out.append((float(a), rig_crlb(r, motion, camera_bound, edge_noise_px=edge_noise_px, constraint=constraint)))
    return out
