"""Several line-scan cameras in one world frame: the rig file, the ball's world motion and each camera's view of it.

A rig holds two or more cameras (geometry.md's camera of Eq. (1), each with
a pose ``X_cam = R X_world + T``), one shared world frame and one clock.
Camera ``k``'s clock reads ``t_cam = t_rig + clock_offset_s``; an offset may
be unknown, to be estimated by the joint fit.

The ball's motion in the world frame is the dynamic sphere of the paper's
Eq. (8) with a known constant acceleration ``g`` (gravity):

    X(t) = P + V (t - t_ref) + g (t - t_ref)^2 / 2        (world, rig clock)

Camera ``k`` sees it cross its viewing plane (camera ``x = 0``, world
``r0 . X + T0 = 0`` with ``r0`` the first row of ``R``) at the root ``tau``
of ``r0 . X(t_ref + tau) + T0 = 0`` nearest to the straight-line one, and its
six parameters (:data:`ballscan.geometry.motion.PARAM_NAMES`, camera frame
and clock) are

    t_c = t_ref + tau + offset,  (0, y0, z0) = R X(t_ref + tau) + T,
    v = R (V + g tau).

:func:`camera_params` returns them and their analytic Jacobian with respect
to ``(P, V)`` (by the implicit function theorem on ``tau``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

import numpy as np

from ..errors import CameraFileError
from .camera import LineScanCamera, _read_toml, camera_from_dict, load_camera
from .motion import BallMotion

__all__ = [
    "Rig",
    "RigCamera",
    "WorldMotion",
    "PlaneCrossing",
    "ViewingPlane",
    "camera_params",
    "load_rig",
    "plane_crossing",
    "rig_from_dict",
    "save_rig",
    "turned_camera",
    "viewing_plane",
    "world_crossing",
]

_RIG_KEYS = {"gravity_mps2", "match_window_s", "camera"}
_CAMERA_RIG_KEYS = {"name", "file", "clock_offset_s", "clock_sigma_s"}


@dataclass(frozen=True)
class RigCamera:
    """One camera of a rig.

    Attributes
    ----------
    name : str
        Unique within the rig (used in results and on the command line).
    camera : LineScanCamera
        With its pose in the rig's world frame (and the rig's gravity).
    clock_offset_s : float or None
        ``t_cam - t_rig`` in seconds; None: unknown (estimated).
    clock_sigma_s : float
        1-sigma of the prior knowledge of an unknown offset about 0 (s):
        it widens the time window in which balls are matched across cameras.
    """

    name: str
    camera: LineScanCamera
    clock_offset_s: float | None = 0.0
    clock_sigma_s: float = 0.0

    def __post_init__(self) -> None:
        src = self.camera.source
        if not isinstance(self.name, str) or not self.name:
            raise CameraFileError(src, f"must be a non-empty string, got {self.name!r}", "name")
        if not self.camera.has_pose:
            raise CameraFileError(src, f"camera {self.name!r} needs a [pose] in the rig's world frame", "pose")
        if self.clock_offset_s is not None and not math.isfinite(self.clock_offset_s):
            raise CameraFileError(src, f"must be finite or \"unknown\", got {self.clock_offset_s!r}", "clock_offset_s")
        if not (math.isfinite(self.clock_sigma_s) and self.clock_sigma_s >= 0):
            raise CameraFileError(src, f"must be a non-negative number, got {self.clock_sigma_s!r}", "clock_sigma_s")

    @property
    def clock_known(self) -> bool:
        return self.clock_offset_s is not None


@dataclass(frozen=True)
class Rig:
    """Two or more posed cameras with one world frame and one clock.

    Attributes
    ----------
    cameras : tuple of RigCamera
        The first camera with a known clock offset is the reference: joint
        results give the crossing of its viewing plane.
    gravity_mps2 : tuple of 3 floats or None
        Known acceleration in the world frame (m/s^2), set on every camera.
    match_window_s : float
        Least half-width of the time window in which one ball's crossings
        of different cameras are matched (s), added to the predicted
        crossing's uncertainty and the clocks'.
    source : str
        The rig file (for messages).
    """

    cameras: tuple[RigCamera, ...]
    gravity_mps2: tuple[float, float, float] | None = None
    match_window_s: float = 1e-3
    source: str = field(default="<rig>", compare=False, repr=False)

    def __post_init__(self) -> None:
        src = self.source
        if len(self.cameras) < 1:
            raise CameraFileError(src, "needs at least one [[camera]]", "camera")
        names = [c.name for c in self.cameras]
        dup = sorted({n for n in names if names.count(n) > 1})
        if dup:
            raise CameraFileError(src, f"camera name {dup[0]!r} is used twice", "camera.name")
        if not any(c.clock_known for c in self.cameras):
            raise CameraFileError(src, "at least one camera needs a known clock_offset_s (the rig's clock)", "camera.clock_offset_s")
        if not (math.isfinite(self.match_window_s) and self.match_window_s >= 0):
            raise CameraFileError(src, f"must be a non-negative number of seconds, got {self.match_window_s!r}", "match_window_s")

    @property
    def names(self) -> tuple[str, ...]:
        return tuple(c.name for c in self.cameras)

    @property
    def reference(self) -> int:
        """Index of the reference camera (the first with a known clock)."""
        return next(k for k, c in enumerate(self.cameras) if c.clock_known)

    @property
    def unknown_clocks(self) -> tuple[int, ...]:
        """Indices of the cameras whose clock offset is estimated."""
        return tuple(k for k, c in enumerate(self.cameras) if not c.clock_known)

    def gravity_vector(self) -> np.ndarray:
        return np.zeros(3) if self.gravity_mps2 is None else np.asarray(self.gravity_mps2, dtype=float)

    def camera(self, name: str) -> RigCamera:
        for c in self.cameras:
            if c.name == name:
                return c
        raise ValueError(f"no camera {name!r} in the rig (cameras: {', '.join(self.names)})")

    def with_camera(self, index: int, rig_camera: RigCamera) -> "Rig":
        """A copy with camera ``index`` replaced."""
        cams = list(self.cameras)
        cams[index] = rig_camera
        return replace(self, cameras=tuple(cams))

    def to_dict(self) -> dict[str, Any]:
        """The rig file's content (cameras inline)."""
        d: dict[str, Any] = {"match_window_s": float(self.match_window_s)}
        if self.gravity_mps2 is not None:
            d["gravity_mps2"] = [float(v) for v in self.gravity_mps2]
        cams = []
        for c in self.cameras:
            cd: dict[str, Any] = {"name": c.name}
            cd["clock_offset_s"] = "unknown" if c.clock_offset_s is None else float(c.clock_offset_s)
            if c.clock_sigma_s:
                cd["clock_sigma_s"] = float(c.clock_sigma_s)
            cam = c.camera.to_dict()
            cam.pop("gravity_mps2", None)
            cd.update(cam)
            cams.append(cd)
        d["camera"] = cams
        return d


# ------------------------------------------------------------------ motion


@dataclass(frozen=True)
class WorldMotion:
    """The ball's motion in the rig's world frame and clock (Eq. (8) with gravity).

    Attributes
    ----------
    radius_m : float
    t_ref_s : float
        Rig-clock time at which the centre is ``position_m`` (s).
    position_m, velocity_mps : tuple of 3 floats
        Centre (m) and velocity (m/s) at ``t_ref_s``, world frame.
    gravity_mps2 : tuple of 3 floats
        Known acceleration, world frame (m/s^2).
    """

    radius_m: float
    t_ref_s: float
    position_m: tuple[float, float, float]
    velocity_mps: tuple[float, float, float]
    gravity_mps2: tuple[float, float, float] = (0.0, 0.0, 0.0)

    def __post_init__(self) -> None:
        if not (math.isfinite(self.radius_m) and self.radius_m > 0):
            raise ValueError(f"radius_m: must be positive and finite, got {self.radius_m!r}")
        for key in ("position_m", "velocity_mps", "gravity_mps2"):
            a = np.asarray(getattr(self, key), dtype=float).reshape(-1)
            if a.shape != (3,) or not np.all(np.isfinite(a)):
                raise ValueError(f"{key}: expected 3 finite values, got {getattr(self, key)!r}")
            object.__setattr__(self, key, tuple(float(v) for v in a))

    @property
    def state(self) -> np.ndarray:
        """``(P, V)`` as an array (6,)."""
        return np.array([*self.position_m, *self.velocity_mps])

    @property
    def speed_mps(self) -> float:
        return float(np.linalg.norm(self.velocity_mps))

    def centre(self, t_s: np.ndarray) -> np.ndarray:
        """Centre (..., 3) at rig times ``t_s`` (m)."""
        dt = np.asarray(t_s, dtype=float)[..., None] - self.t_ref_s
        g = np.asarray(self.gravity_mps2)
        return np.asarray(self.position_m) + np.asarray(self.velocity_mps) * dt + 0.5 * g * dt * dt

    def velocity_at(self, t_s: np.ndarray) -> np.ndarray:
        dt = np.asarray(t_s, dtype=float)[..., None] - self.t_ref_s
        return np.asarray(self.velocity_mps) + np.asarray(self.gravity_mps2) * dt

    def at(self, t_s: float) -> "WorldMotion":
        """The same motion referred to rig time ``t_s``."""
        return replace(self, t_ref_s=float(t_s), position_m=tuple(self.centre(t_s)), velocity_mps=tuple(self.velocity_at(t_s)))

    def in_camera(self, rig_camera: RigCamera, clock_offset_s: float | None = None) -> BallMotion | None:
        """The camera's view: its :class:`BallMotion` (camera frame and clock), or None if the ball never crosses its plane.

        ``clock_offset_s`` replaces the camera's (needed where it is unknown).
        """
        off = rig_camera.clock_offset_s if clock_offset_s is None else clock_offset_s
        if off is None:
            raise ValueError(f"camera {rig_camera.name!r}: its clock offset is unknown; give one")
        theta, _, ok = camera_params(self.state, rig_camera.camera, self.t_ref_s, np.asarray(self.gravity_mps2), off)
        if not ok:
            return None
        acc = tuple(rig_camera.camera.rotation_matrix @ np.asarray(self.gravity_mps2))
        return BallMotion.from_params(theta, self.radius_m, acc)

    def to_dict(self) -> dict[str, Any]:
        """geometry.md truth keys in the world frame (``t_c_s``: the time of ``position_m``)."""
        return {
            "radius_m": self.radius_m,
            "t_c_s": self.t_ref_s,
            "position_m": list(self.position_m),
            "velocity_mps": list(self.velocity_mps),
            "speed_mps": self.speed_mps,
            "gravity_mps2": list(self.gravity_mps2),
        }

    @classmethod
    def from_dict(cls, d: dict[str, Any]) -> "WorldMotion":
        return cls(float(d["radius_m"]), float(d["t_c_s"]), tuple(d["position_m"]), tuple(d["velocity_mps"]), tuple(d.get("gravity_mps2", (0.0, 0.0, 0.0))))


def _crossing_tau(a: float, b: float, c: float) -> tuple[float, bool]:
    """Root of ``a + b tau + c tau^2 / 2 = 0`` nearest the straight line's ``-a / b`` (s), and whether it exists."""
    if b == 0.0 and c == 0.0:
        return math.nan, False
    if abs(c) < 1e-300 or abs(a * c) < 1e-12 * b * b:
        if b == 0.0:
            return math.nan, False
        return -a / b, True
    disc = b * b - 2.0 * a * c
    if disc < 0:
        return (-a / b if b != 0 else math.nan), False
    q = b + math.copysign(math.sqrt(disc), b)
    return -2.0 * a / q, True


def world_crossing(
    state: np.ndarray, camera: LineScanCamera, t_ref_s: float, gravity_mps2: np.ndarray
) -> tuple[float, np.ndarray, np.ndarray, np.ndarray, bool]:
    """Where and when a world motion crosses a camera's viewing plane, and the derivatives (Eq. (8), world frame).

    Parameters
    ----------
    state : ndarray (6,)
        ``(P, V)``: the world centre at ``t_ref_s`` (m) and velocity (m/s).
    camera : LineScanCamera
        With its pose (``X_cam = R X_world + T``).
    t_ref_s : float
        Rig time of ``P`` (s).
    gravity_mps2 : ndarray (3,)
        World acceleration (m/s^2).

    Returns
    -------
    t_s : float
        Rig time of the crossing.
    centre_m, velocity_mps : ndarray (3,)
        The centre and velocity then, world frame.
    jacobian : ndarray (7, 6)
        ``d (t, centre, velocity) / d (P, V)``.
    ok : bool
        False when the ball never crosses the plane (the straight-line
        crossing is then used; the Jacobian may be infinite).
    """
    R, T = camera.rotation_matrix, camera.translation_vector
    P, V, g = state[:3], state[3:6], np.asarray(gravity_mps2, dtype=float)
    r0 = R[0]
    tau, ok = _crossing_tau(float(r0 @ P + T[0]), float(r0 @ V), float(r0 @ g))
    X = P + V * tau + 0.5 * g * tau * tau
    vw = V + g * tau
    vn = float(r0 @ vw)  # d/dtau of r0 . X(tau) + T0
    with np.errstate(divide="ignore", invalid="ignore"):
        dtau = np.concatenate([-r0, -r0 * tau]) / vn
    J = np.zeros((7, 6))
    J[0] = dtau
    J[1:4] = np.hstack([np.eye(3), np.eye(3) * tau]) + np.outer(vw, dtau)
    J[4:7] = np.hstack([np.zeros((3, 3)), np.eye(3)]) + np.outer(g, dtau)
    return t_ref_s + tau, X, vw, J, ok


def camera_params(
    state: np.ndarray, camera: LineScanCamera, t_ref_s: float, gravity_mps2: np.ndarray, clock_offset_s: float
) -> tuple[np.ndarray, np.ndarray, bool]:
    """One camera's motion parameters of a world motion and their Jacobian (Eq. (8) seen through Eq. (1)'s pose).

    Parameters
    ----------
    state, camera, t_ref_s, gravity_mps2
        As for :func:`world_crossing`.
    clock_offset_s : float
        ``t_cam - t_rig`` (s).

    Returns
    -------
    theta : ndarray (6,)
        ``(t_c, y0, z0, vx, vy, vz)`` in the camera's frame and clock.
    jacobian : ndarray (6, 6)
        ``d theta / d (P, V)``; ``d t_c / d offset`` is 1 (not included).
    ok : bool
        False when the ball never crosses the viewing plane.
    """
    R, T = camera.rotation_matrix, camera.translation_vector
    t, X, vw, Jw, ok = world_crossing(state, camera, t_ref_s, gravity_mps2)
    pc = R @ X + T
    vc = R @ vw
    theta = np.array([t + clock_offset_s, pc[1], pc[2], vc[0], vc[1], vc[2]])
    J = np.zeros((6, 6))
    J[0] = Jw[0]
    J[1:3] = (R @ Jw[1:4])[1:3]
    J[3:6] = R @ Jw[4:7]
    return theta, J, ok


def turned_camera(camera: LineScanCamera, point_m: np.ndarray, angle_deg: float) -> LineScanCamera:
    """The camera turned ``angle_deg`` about the line through ``point_m`` along its viewing plane's normal (right-handed).

    Its viewing plane stays the same plane; its optical axis turns within
    it about the point (e.g. the ball's crossing), keeping its distance.
    ``X_cam = R Q^T (X - p) + R p + T`` with ``Q`` the turn (world frame).
    """
    R, T = camera.rotation_matrix, camera.translation_vector
    n = R[0]
    a = math.radians(angle_deg)
    K = np.array([[0.0, -n[2], n[1]], [n[2], 0.0, -n[0]], [-n[1], n[0], 0.0]])
    Q = np.eye(3) + math.sin(a) * K + (1.0 - math.cos(a)) * (K @ K)
    p = np.asarray(point_m, dtype=float)
    R2 = R @ Q.T
    return camera.with_pose(R2, T + R @ p - R2 @ p)


# ------------------------------------------------------------- the planes


@dataclass(frozen=True)
class ViewingPlane:
    """A camera's viewing plane in the world frame: ``normal . X = offset_m``.

    Attributes
    ----------
    normal : ndarray (3,)
        Unit normal (the camera's ``x`` axis in world coordinates).
    offset_m : float
    centre_m : ndarray (3,)
        The camera's projection centre, world frame (m).
    axis : ndarray (3,)
        The optical axis (camera ``z``) in world coordinates.
    sensor : ndarray (3,)
        The sensor's direction (camera ``y``) in world coordinates.
    """

    normal: np.ndarray
    offset_m: float
    centre_m: np.ndarray
    axis: np.ndarray
    sensor: np.ndarray


def viewing_plane(camera: LineScanCamera) -> ViewingPlane:
    """The viewing plane ``x_cam = 0`` of a posed camera in world coordinates (geometry.md's pose)."""
    R, T = camera.rotation_matrix, camera.translation_vector
    return ViewingPlane(R[0].copy(), float(-T[0]), -R.T @ T, R[2].copy(), R[1].copy())


@dataclass(frozen=True)
class PlaneCrossing:
    """Where two viewing planes meet.

    Attributes
    ----------
    parallel : bool
        The planes are parallel (within 1e-9 rad).
    distance_m : float
        Parallel planes: their separation (0: the same plane); else 0.
    angle_deg : float
        Angle between the planes' normals, folded into [0, 90].
    point_m, direction : ndarray (3,) or None
        The line ``point + s direction`` they share (not parallel): the
        point nearest the first camera's centre.
    axes_angle_deg : float
        Angle between the two optical axes (degrees, 0..180).
    """

    parallel: bool
    distance_m: float
    angle_deg: float
    point_m: np.ndarray | None
    direction: np.ndarray | None
    axes_angle_deg: float


def plane_crossing(a: ViewingPlane, b: ViewingPlane) -> PlaneCrossing:
    """The line two viewing planes share, or their separation when parallel."""
    d = np.cross(a.normal, b.normal)
    s = float(np.linalg.norm(d))
    cosn = float(np.clip(abs(a.normal @ b.normal), 0.0, 1.0))
    angle = math.degrees(math.acos(cosn))
    axes = math.degrees(math.acos(float(np.clip(a.axis @ b.axis, -1.0, 1.0))))
    if s < 1e-9:
        sign = 1.0 if a.normal @ b.normal > 0 else -1.0
        return PlaneCrossing(True, abs(b.offset_m * sign - a.offset_m), 0.0, None, None, axes)
    d = d / s
    # the point of both planes nearest a's camera centre: minimise |X - C| on n_a.X = o_a, n_b.X = o_b
    M = np.zeros((5, 5))
    M[:3, :3] = 2.0 * np.eye(3)
    M[:3, 3], M[:3, 4] = a.normal, b.normal
    M[3, :3], M[4, :3] = a.normal, b.normal
    rhs = np.concatenate([2.0 * a.centre_m, [a.offset_m, b.offset_m]])
    sol = np.linalg.solve(M, rhs)
    return PlaneCrossing(False, 0.0, angle, sol[:3], d, axes)


# ----------------------------------------------------------------- the file


def _rig_number(d: dict[str, Any], key: str, src: str, where: str, default: float) -> float:
    if key not in d:
        return default
    v = d[key]
    if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(float(v)):
        raise CameraFileError(src, f"must be a finite number, got {v!r}", f"{where}{key}")
    return float(v)


def _rig_camera(d: Any, k: int, src: str, base: Path, gravity) -> RigCamera:
    where = f"camera[{k}]."
    if not isinstance(d, dict):
        raise CameraFileError(src, "must be a table of camera keys", f"camera[{k}]")
    name = d.get("name", f"camera{k}")
    if not isinstance(name, str) or not name:
        raise CameraFileError(src, f"must be a non-empty string, got {name!r}", where + "name")
    off_raw = d.get("clock_offset_s", 0.0)
    if isinstance(off_raw, str):
        if off_raw != "unknown":
            raise CameraFileError(src, f"must be a number of seconds or \"unknown\", got {off_raw!r}", where + "clock_offset_s")
        offset = None
    else:
        offset = _rig_number(d, "clock_offset_s", src, where, 0.0)
    sigma = _rig_number(d, "clock_sigma_s", src, where, 0.0)
    if sigma < 0:
        raise CameraFileError(src, f"must not be negative, got {sigma!r}", where + "clock_sigma_s")
    keys = {k2: v for k2, v in d.items() if k2 not in _CAMERA_RIG_KEYS}
    if "file" in d:
        if not isinstance(d["file"], str):
            raise CameraFileError(src, f"must be a path string, got {d['file']!r}", where + "file")
        path = Path(d["file"])
        cam = load_camera(path if path.is_absolute() else base / path)
        merged = cam.to_dict()
        merged.update(keys)  # the rig's keys (e.g. its [pose]) win over the file's
        keys = merged
    if gravity is not None:
        if "gravity_mps2" in keys and not np.allclose(keys["gravity_mps2"], gravity):
            raise CameraFileError(src, "differs from the rig's gravity_mps2 (one world, one gravity)", where + "gravity_mps2")
        keys["gravity_mps2"] = list(gravity)
    cam = camera_from_dict(keys, source=f"{src} [camera {name}]")
    if not cam.has_pose:
        raise CameraFileError(src, f"camera {name!r} needs a [pose] in the rig's world frame", where + "pose")
    return RigCamera(name, cam, offset, sigma)


def rig_from_dict(d: dict[str, Any], source: str = "<rig>", base: Path | None = None) -> Rig:
    """Build and validate a rig from its TOML content (docs/geometry.md, "Rig file").

    ``base`` is the folder that camera ``file`` paths are relative to.
    """
    unknown = set(d) - _RIG_KEYS
    if unknown:
        raise CameraFileError(source, "unknown key (allowed: " + ", ".join(sorted(_RIG_KEYS)) + ")", sorted(unknown)[0])
    gravity = None
    if "gravity_mps2" in d:
        g = np.asarray(d["gravity_mps2"], dtype=float) if isinstance(d["gravity_mps2"], list) else None
        if g is None or g.shape != (3,) or not np.all(np.isfinite(g)):
            raise CameraFileError(source, f"must be 3 finite numbers, got {d['gravity_mps2']!r}", "gravity_mps2")
        gravity = tuple(float(v) for v in g)
    cams = d.get("camera")
    if not isinstance(cams, list) or not cams:
        raise CameraFileError(source, "missing: give one [[camera]] table per camera", "camera")
    base = Path(".") if base is None else base
    rig_cams = tuple(_rig_camera(c, k, source, base, gravity) for k, c in enumerate(cams))
    window = _rig_number(d, "match_window_s", source, "", 1e-3)
    return Rig(rig_cams, gravity, window, source=source)


def load_rig(path: str | Path) -> Rig:
    """Read and validate a rig TOML file.

    Raises
    ------
    CameraFileError
        With a one-line message naming the file and the key.
    """
    path = Path(path)
    return rig_from_dict(_read_toml(path, "rig"), source=str(path), base=path.parent)


def save_rig(rig: Rig, path: str | Path, comment: str | None = None) -> None:
    """Write a rig as TOML (cameras inline)."""
    import tomli_w

    text = tomli_w.dumps(rig.to_dict())
    if comment:
        text = "".join(f"# {line}\n" for line in comment.splitlines()) + text
    Path(path).write_text(text)
