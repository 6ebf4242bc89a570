"""Line-scan camera model (paper Sec. 2.A, Eq. (1)-(2); geometry.md).

The camera frame has its origin at the projection centre, ``z`` along the
optical axis, ``y`` along the linear sensor and ``x`` normal to the viewing
plane ``x = 0``.  A point ``(0, y, z)`` with ``z > 0`` images at

    u = c + f * n_d,   n = y / z,   n_d = n (1 + k1 n^2 + k2 n^4)

in pixels (pixel ``j`` is centred at ``u = j``).  The paper writes the same
projection as ``y' = -f y / z`` on the physical image plane ``z = -f``
(Eq. (2)); here ``y' = -(u_undistorted - c)``.
"""

from __future__ import annotations

import copy
import math
import tomllib
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

import numpy as np

from ..errors import CameraFileError, GeometryError
from ..inputs import read_small_text
from ..outputs import atomic_write_text
from .lens import distorted, distortion_slope, project, undistorted

__all__ = [
    "LineScanCamera",
    "Eq1Params",
    "load_camera",
    "save_camera",
    "camera_from_eq1",
    "line_times",
    "crop_camera",
]

_ORTHO_TOL = 1e-6


@dataclass(frozen=True)
class LineScanCamera:
    """A calibrated line-scan camera.

    Parameters
    ----------
    width : int
        Number of pixels on the line sensor, indexed ``0 .. width-1``.
    focal_px : float
        Focal length ``f`` in pixels.
    principal_px : float
        Principal point ``c`` along the sensor, in pixels.
    line_rate_hz : float
        Lines per second; line ``i`` is centred at ``t_i = i / line_rate_hz``.
    exposure_s : float or None
        Exposure time ``tau`` in seconds, ``0 < tau <= 1 / line_rate_hz``;
        ``None`` means a full line period.
    k1, k2 : float
        Radial distortion on the normalised coordinate ``n = y / z``.
    crossing : {"+x", "-x"} or None
        Known sign of ``V.x``; ``None`` when unknown (estimates report
        ``V.x >= 0``).
    rotation : tuple of tuple of float or None
        World -> camera rotation (``X_cam = R @ X_world + t``), or ``None``.
    translation_m : tuple of float or None
        World -> camera translation in metres.
    gravity_mps2 : tuple of float or None
        Known constant acceleration in the world frame (needs a pose).
    defocus_px : float or None
        Diameter of the lens's blur circle on the sensor for the balls'
        distances, pixels (:mod:`ballscan.measure.defocus`); ``None``: not
        known, measured on each ball's edges.
    """

    width: int
    focal_px: float
    principal_px: float
    line_rate_hz: float
    exposure_s: float | None = None
    k1: float = 0.0
    k2: float = 0.0
    crossing: str | None = None
    rotation: tuple[tuple[float, float, float], ...] | None = None
    translation_m: tuple[float, float, float] | None = None
    gravity_mps2: tuple[float, float, float] | None = None
    defocus_px: float | None = None
    source: str = field(default="<camera>", compare=False, repr=False)

    def __post_init__(self) -> None:
        _validate(self)

    # ------------------------------------------------------------------ timing
    @property
    def exposure(self) -> float:
        """Exposure time in seconds (a full line period when not set)."""
        return self.exposure_s if self.exposure_s is not None else 1.0 / self.line_rate_hz

    @property
    def has_pose(self) -> bool:
        return self.rotation is not None

    @property
    def rotation_matrix(self) -> np.ndarray:
        """World -> camera rotation as a (3, 3) array (identity without a pose)."""
        if self.rotation is None:
            return np.eye(3)
        return np.asarray(self.rotation, dtype=float)

    @property
    def translation_vector(self) -> np.ndarray:
        """World -> camera translation in metres (zeros without a pose)."""
        if self.translation_m is None:
            return np.zeros(3)
        return np.asarray(self.translation_m, dtype=float)

    @property
    def crossing_sign(self) -> float:
        """+1 or -1 when the crossing direction is known, +1 otherwise."""
        return -1.0 if self.crossing == "-x" else 1.0

    def gravity_camera_mps2(self) -> np.ndarray:
        """The known acceleration in the camera frame (zeros when none)."""
        if self.gravity_mps2 is None:
            return np.zeros(3)
        return self.rotation_matrix @ np.asarray(self.gravity_mps2, dtype=float)

    # -------------------------------------------------------------- distortion
    def distort(self, n: np.ndarray) -> np.ndarray:
        """Radial distortion ``n_d = n (1 + k1 n^2 + k2 n^4)`` (dimensionless), Eq. (2) (:mod:`ballscan.geometry.lens`)."""
        return distorted(np.asarray(n, dtype=float), self.k1, self.k2)

    def distort_derivative(self, n: np.ndarray) -> np.ndarray:
        """``d n_d / d n = 1 + 3 k1 n^2 + 5 k2 n^4``."""
        return distortion_slope(np.asarray(n, dtype=float), self.k1, self.k2)

    def undistort(self, n_d: np.ndarray, tol_px: float = 1e-9) -> np.ndarray:
        """Invert :meth:`distort` by Newton's method to ``tol_px`` pixels (:func:`ballscan.geometry.lens.undistorted`).

        Parameters
        ----------
        n_d : array_like
            Distorted normalised coordinates.
        tol_px : float
            Stopping tolerance expressed in pixels on the sensor.

        Raises
        ------
        GeometryError
            If a coordinate lies outside the monotonic range of ``k1, k2``.
        """
        n, converged = undistorted(n_d, self.k1, self.k2, tol_px / self.focal_px)
        if not converged:
            raise GeometryError("inverse distortion did not converge: coordinate outside the monotonic range of k1, k2")
        return n

    # -------------------------------------------------------------- projection
    def project_normalised(self, n: np.ndarray) -> np.ndarray:
        """Pixel coordinate ``u`` of the undistorted normalised coordinate ``n = y / z`` (:func:`ballscan.geometry.lens.project`)."""
        return project(np.asarray(n, dtype=float), self.focal_px, self.principal_px, self.k1, self.k2)

    def project(self, y_m: np.ndarray, z_m: np.ndarray) -> np.ndarray:
        """Project points ``(0, y, z)`` of the viewing plane to ``u`` (pixels).

        Eq. (2) in geometry.md's sign convention: ``u = c + f * distort(y / z)``.

        Raises
        ------
        GeometryError
            If any point lies on or behind the camera (``z <= 0``).
        """
        y_m = np.asarray(y_m, dtype=float)
        z_m = np.asarray(z_m, dtype=float)
        if np.any(z_m <= 0):
            raise GeometryError("cannot project a point on or behind the camera (z <= 0)")
        return self.project_normalised(y_m / z_m)

    def backproject(self, u_px: np.ndarray) -> np.ndarray:
        """Undistorted normalised coordinate ``n = y / z`` of the ray through ``u``.

        The ray is ``(0, n, 1) * s`` for ``s > 0``; inverse distortion is
        iterated to 1e-9 px.
        """
        n_d = (np.asarray(u_px, dtype=float) - self.principal_px) / self.focal_px
        return self.undistort(n_d)

    # ---------------------------------------------------------------- frames
    def world_to_camera(self, points_world: np.ndarray) -> np.ndarray:
        """Points (..., 3) from world to camera frame: ``R @ X + t``."""
        p = np.asarray(points_world, dtype=float)
        return p @ self.rotation_matrix.T + self.translation_vector

    def camera_to_world(self, points_camera: np.ndarray) -> np.ndarray:
        """Points (..., 3) from camera to world frame: ``R.T @ (X - t)``."""
        p = np.asarray(points_camera, dtype=float)
        return (p - self.translation_vector) @ self.rotation_matrix

    def vectors_to_world(self, vectors_camera: np.ndarray) -> np.ndarray:
        """Free vectors (velocities) from camera to world frame."""
        return np.asarray(vectors_camera, dtype=float) @ self.rotation_matrix

    def vectors_to_camera(self, vectors_world: np.ndarray) -> np.ndarray:
        """Free vectors (velocities) from world to camera frame."""
        return np.asarray(vectors_world, dtype=float) @ self.rotation_matrix.T

    # -------------------------------------------------------------- Eq. (1)
    def to_eq1(self) -> "Eq1Params":
        """The paper's general calibrated model, Eq. (1).

        A world point ``(X, Y, Z)`` on the viewing plane satisfies
        ``X = p Y + q Z + r`` and images at
        ``y' = (n1 Y + n2 Z + n3) / (n4 Y + n5 Z + 1)``, where ``y'`` is the
        paper's undistorted image coordinate ``y' = -f y / z`` (pixels),
        i.e. ``u = c - y'`` before distortion.

        Raises
        ------
        GeometryError
            If the viewing plane cannot be written as ``X = p Y + q Z + r``
            (it contains the world X direction) or if the denominator's
            constant term vanishes (the camera-frame depth of the world point
            ``(r, 0, 0)`` is zero).
        """
        R = self.rotation_matrix
        t = self.translation_vector
        if abs(R[0, 0]) < 1e-12:
            raise GeometryError("Eq. (1) is undefined for this pose: the viewing plane is parallel to the world X axis (R[0,0] = 0)")
        p = -R[0, 1] / R[0, 0]
        q = -R[0, 2] / R[0, 0]
        r = -t[0] / R[0, 0]
        # camera y and z as affine functions of (Y, Z) on the plane
        a = np.array([R[1, 0] * p + R[1, 1], R[1, 0] * q + R[1, 2], R[1, 0] * r + t[1]])
        b = np.array([R[2, 0] * p + R[2, 1], R[2, 0] * q + R[2, 2], R[2, 0] * r + t[2]])
        if abs(b[2]) < 1e-12 * max(1.0, np.abs(b).max()):
            raise GeometryError("Eq. (1) is undefined for this pose: its denominator's constant term vanishes (the world point (r, 0, 0) is at zero depth)")
        f = self.focal_px
        n = -f * a / b[2]
        return Eq1Params(n1=n[0], n2=n[1], n3=n[2], n4=b[0] / b[2], n5=b[1] / b[2], p=p, q=q, r=r)

    def with_pose(self, rotation: np.ndarray, translation_m: np.ndarray) -> "LineScanCamera":
        """A copy of this camera with another world pose."""
        rot = tuple(tuple(float(v) for v in row) for row in np.asarray(rotation, dtype=float))
        tr = tuple(float(v) for v in np.asarray(translation_m, dtype=float))
        return replace(self, rotation=rot, translation_m=tr)  # type: ignore[arg-type]

    def to_dict(self) -> dict[str, Any]:
        """The geometry.md TOML content as a dict (optional keys only when set)."""
        d: dict[str, Any] = {
            "width": int(self.width),
            "focal_px": float(self.focal_px),
            "principal_px": float(self.principal_px),
            "line_rate_hz": float(self.line_rate_hz),
        }
        if self.exposure_s is not None:
            d["exposure_s"] = float(self.exposure_s)
        d["k1"] = float(self.k1)
        d["k2"] = float(self.k2)
        if self.crossing is not None:
            d["crossing"] = self.crossing
        if self.gravity_mps2 is not None:
            d["gravity_mps2"] = [float(v) for v in self.gravity_mps2]
        if self.defocus_px is not None:
            d["defocus_px"] = float(self.defocus_px)
        if self.rotation is not None:
            d["pose"] = {
                "rotation": [[float(v) for v in row] for row in self.rotation],
                "translation": [float(v) for v in (self.translation_m or (0.0, 0.0, 0.0))],
            }
        return d


@dataclass(frozen=True)
class Eq1Params:
    """Parameters of the paper's Eq. (1) (``y'`` in pixels, world in metres)."""

    n1: float
    n2: float
    n3: float
    n4: float
    n5: float
    p: float
    q: float
    r: float

    def image_coordinate(self, Y: np.ndarray, Z: np.ndarray) -> np.ndarray:
        """``y'`` of world points on the viewing plane, Eq. (1), first line."""
        return (self.n1 * Y + self.n2 * Z + self.n3) / (self.n4 * Y + self.n5 * Z + 1.0)

    def plane_x(self, Y: np.ndarray, Z: np.ndarray) -> np.ndarray:
        """World ``X`` of the viewing plane, Eq. (1), second line."""
        return self.p * Y + self.q * Z + self.r


def camera_from_eq1(
    params: Eq1Params,
    *,
    width: int,
    focal_px: float,
    principal_px: float,
    line_rate_hz: float,
    origin_in_front: bool = True,
    **kwargs: Any,
) -> LineScanCamera:
    """Recover the camera pose from the paper's Eq. (1) parameters and ``f``.

    Eq. (1) is invariant under a half turn of the camera about its ``x`` axis
    (``(y, z) -> (-y, -z)`` leaves ``y / z`` unchanged), so one bit is not in
    the parameters: ``origin_in_front`` says whether the world point
    ``(r, 0, 0)`` of the viewing plane lies in front of the camera (``z > 0``).

    Parameters
    ----------
    params : Eq1Params
        n1..n5 (pixels, 1/m), p, q (dimensionless), r (m).
    width, focal_px, principal_px, line_rate_hz
        Intrinsics of the camera (pixels, Hz).
    origin_in_front : bool
        Resolves the half-turn ambiguity (see above).
    **kwargs
        Other :class:`LineScanCamera` fields (exposure, distortion, ...).
    """
    p, q, r, f = params.p, params.q, params.r, float(focal_px)
    norm = math.sqrt(1.0 + p * p + q * q)
    row0 = np.array([1.0, -p, -q]) / norm
    # The plane normal's sign is fixed below by det(R) = +1.
    a_over_b3 = -np.array([params.n1, params.n2, params.n3]) / f
    b_over_b3 = np.array([params.n4, params.n5, 1.0])
    k = 1.0 + p * p + q * q

    def row_from(coeff: np.ndarray) -> np.ndarray:
        r0 = (p * coeff[0] + q * coeff[1]) / k
        return np.array([r0, coeff[0] - r0 * p, coeff[1] - r0 * q])

    row1_u = row_from(a_over_b3)
    row2_u = row_from(b_over_b3)
    scale = np.linalg.norm(row2_u)
    if scale == 0 or not np.isfinite(scale):
        raise GeometryError("Eq. (1) parameters do not describe a camera pose")
    b3 = (1.0 if origin_in_front else -1.0) / scale
    row1 = row1_u * b3
    row2 = row2_u * b3
    R = np.vstack([row0, row1, row2])
    if np.linalg.det(R) < 0:
        R[0] = -R[0]
    if not np.allclose(R @ R.T, np.eye(3), atol=1e-6):
        raise GeometryError("Eq. (1) parameters are inconsistent with focal_px: the recovered rotation is not orthonormal")
    t0 = -r * R[0, 0]
    t1 = a_over_b3[2] * b3 - R[1, 0] * r
    t2 = b3 - R[2, 0] * r
    cam = LineScanCamera(width=width, focal_px=f, principal_px=principal_px, line_rate_hz=line_rate_hz, **kwargs)
    return cam.with_pose(R, np.array([t0, t1, t2]))


def line_times(camera: LineScanCamera, n_lines: int, timestamps_s: np.ndarray | None = None) -> np.ndarray:
    """Centre time of each scan line in seconds.

    ``t_i = i / line_rate_hz`` unless per-line ``timestamps_s`` are given
    (strictly increasing, one per line), which then replace them.
    """
    if timestamps_s is None:
        return np.arange(n_lines, dtype=float) / camera.line_rate_hz
    ts = np.asarray(timestamps_s, dtype=float)
    if ts.ndim != 1 or ts.size != n_lines:
        raise ValueError(f"timestamps: expected {n_lines} values (one per line), got {ts.size}")
    if not np.all(np.isfinite(ts)):
        raise ValueError("timestamps: not all finite")
    bad = np.flatnonzero(np.diff(ts) <= 0)
    if bad.size:
        k = int(bad[0])
        raise ValueError(f"timestamps: not strictly increasing (line {k + 1}: {float(ts[k + 1])!r} s after {float(ts[k])!r} s)")
    return ts


# --------------------------------------------------------------------- I/O

_KNOWN_KEYS = {"width", "focal_px", "principal_px", "line_rate_hz", "exposure_s", "k1", "k2", "crossing", "gravity_mps2", "pose", "defocus_px"}
#: Largest blur circle taken as a real lens's, pixels.
MAX_DEFOCUS_PX = 100.0

#: The ranges a real line-scan rig lies in, far wider than any camera sold:
#: a value outside is a typing or unit error, refused at load (it would make
#: every later computation overflow, or run for hours over an absurd
#: number of pixels or lines).  ``principal_px`` within this many sensor
#: widths of the sensor; ``exposure_s`` at least :data:`MIN_EXPOSURE_S`.
PLAUSIBLE_RANGES = {
    "width": (2, 1 << 20, "pixels"),
    "focal_px": (1.0, 1e7, "pixels"),
    "line_rate_hz": (1e-3, 1e8, "lines per second"),
    "k1": (-1e6, 1e6, ""),
    "k2": (-1e6, 1e6, ""),
}
PRINCIPAL_WIDTHS = 100
MIN_EXPOSURE_S = 1e-10
#: Largest translation of the pose (m) and gravity (m/s^2) taken as real.
MAX_TRANSLATION_M = 1e6
MAX_GRAVITY_MPS2 = 1e3
#: A camera file is a dozen lines, a rig file a few dozen; anything beyond this many bytes is neither.
MAX_CAMERA_FILE_BYTES = 1 << 20


def _validate(cam: LineScanCamera) -> None:
    src = cam.source

    def bad(key: str, problem: str) -> CameraFileError:
        return CameraFileError(src, problem, key)

    if isinstance(cam.width, bool) or not isinstance(cam.width, (int, np.integer)):
        raise bad("width", f"must be a whole number of pixels, got {cam.width!r}")
    if cam.width < 2:
        raise bad("width", f"must be at least 2 pixels, got {cam.width}")
    for key in ("focal_px", "principal_px", "line_rate_hz", "k1", "k2"):
        v = getattr(cam, key)
        if isinstance(v, bool) or not isinstance(v, (int, float, np.floating, np.integer)):
            raise bad(key, f"must be a number, got {v!r}")
        if not math.isfinite(float(v)):
            raise bad(key, f"must be finite, got {v!r}")
    if cam.focal_px <= 0:
        raise bad("focal_px", f"must be positive, got {cam.focal_px!r}")
    if cam.line_rate_hz <= 0:
        raise bad("line_rate_hz", f"must be positive, got {cam.line_rate_hz!r}")
    for key, (lo, hi, unit) in PLAUSIBLE_RANGES.items():
        v = getattr(cam, key)
        if not lo <= v <= hi:
            raise bad(key, f"{v!r} is outside the range of any line-scan camera ({lo:g} to {hi:g}{' ' + unit if unit else ''})")
    reach = PRINCIPAL_WIDTHS * cam.width
    if not -reach <= cam.principal_px <= cam.width + reach:
        raise bad("principal_px", f"{cam.principal_px!r} is more than {PRINCIPAL_WIDTHS} sensor widths off the sensor")
    if cam.exposure_s is not None:
        e = cam.exposure_s
        if isinstance(e, bool) or not isinstance(e, (int, float, np.floating)) or not math.isfinite(float(e)):
            raise bad("exposure_s", f"must be a finite number, got {e!r}")
        if e <= 0:
            raise bad("exposure_s", f"must be positive, got {e!r}")
        if e < MIN_EXPOSURE_S:
            raise bad("exposure_s", f"{e!r} s is shorter than any camera's exposure ({MIN_EXPOSURE_S:g} s)")
        if e > (1.0 / cam.line_rate_hz) * (1 + 1e-9):
            raise bad("exposure_s", f"{e!r} s exceeds the line period 1/line_rate_hz = {1.0 / cam.line_rate_hz!r} s")
    if cam.defocus_px is not None:
        b = cam.defocus_px
        if isinstance(b, bool) or not isinstance(b, (int, float, np.floating)) or not math.isfinite(float(b)):
            raise bad("defocus_px", f"must be a finite number, got {b!r}")
        if not 0 <= b <= MAX_DEFOCUS_PX:
            raise bad("defocus_px", f"{b!r} is outside 0 to {MAX_DEFOCUS_PX:g} pixels")
    if cam.crossing not in (None, "+x", "-x"):
        raise bad("crossing", f"must be \"+x\" or \"-x\", got {cam.crossing!r}")
    # Distortion must stay monotonic across the sensor, or pixels map to two rays.
    n_edge = max(abs(0 - cam.principal_px), abs(cam.width - 1 - cam.principal_px)) / cam.focal_px * 1.2
    nn = np.linspace(0.0, n_edge, 257)
    if np.any(cam.distort_derivative(nn) <= 0):
        raise bad("k1", "distortion (k1, k2) is not monotonic across the sensor")
    if cam.rotation is not None:
        R = _as_matrix(cam.rotation, (3, 3), src, "pose.rotation")
        if np.abs(R).max() > 1.0 + _ORTHO_TOL or abs(np.linalg.det(R) - 1.0) > _ORTHO_TOL or not np.allclose(R @ R.T, np.eye(3), atol=_ORTHO_TOL):
            raise bad("pose.rotation", "is not a proper rotation (orthonormal with determinant +1)")
        if cam.translation_m is None:
            raise bad("pose.translation", "missing (a pose needs rotation and translation)")
        t = _as_matrix(cam.translation_m, (3,), src, "pose.translation")
        if np.abs(t).max() > MAX_TRANSLATION_M:
            raise bad("pose.translation", f"more than {MAX_TRANSLATION_M:g} m from the world origin")
    elif cam.translation_m is not None:
        raise bad("pose.rotation", "missing (a pose needs rotation and translation)")
    if cam.gravity_mps2 is not None:
        g = _as_matrix(cam.gravity_mps2, (3,), src, "gravity_mps2")
        if np.abs(g).max() > MAX_GRAVITY_MPS2:
            raise bad("gravity_mps2", f"more than {MAX_GRAVITY_MPS2:g} m/s^2")
        if cam.rotation is None:
            raise bad("gravity_mps2", "needs a [pose] (gravity is given in the world frame)")


def _as_matrix(value: Any, shape: tuple[int, ...], src: str, key: str) -> np.ndarray:
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise CameraFileError(src, f"must be numbers of shape {shape}, got {value!r}", key) from None
    if arr.shape != shape:
        raise CameraFileError(src, f"must have shape {shape}, got {arr.shape}", key)
    if not np.all(np.isfinite(arr)):
        raise CameraFileError(src, "must be finite", key)
    return arr


def _number(d: dict[str, Any], key: str, src: str, *, required: bool, integer: bool = False) -> Any:
    if key not in d:
        if required:
            raise CameraFileError(src, "missing", key)
        return None
    v = d[key]
    if isinstance(v, bool) or not isinstance(v, (int, float)):
        raise CameraFileError(src, f"must be a number, got {type(v).__name__} {v!r}", key)
    if integer:
        if isinstance(v, float):
            if not v.is_integer():
                raise CameraFileError(src, f"must be a whole number, got {v!r}", key)
            v = int(v)
        return v
    if not math.isfinite(float(v)):
        raise CameraFileError(src, f"must be finite, got {v!r}", key)
    return float(v)


def camera_from_dict(d: dict[str, Any], source: str = "<camera>") -> LineScanCamera:
    """Build and validate a camera from geometry.md's TOML keys."""
    unknown = set(d) - _KNOWN_KEYS
    if unknown:
        raise CameraFileError(source, "unknown key (allowed: " + ", ".join(sorted(_KNOWN_KEYS)) + ")", sorted(unknown)[0])
    kw: dict[str, Any] = {
        "width": _number(d, "width", source, required=True, integer=True),
        "focal_px": _number(d, "focal_px", source, required=True),
        "principal_px": _number(d, "principal_px", source, required=True),
        "line_rate_hz": _number(d, "line_rate_hz", source, required=True),
        "exposure_s": _number(d, "exposure_s", source, required=False),
        "k1": _number(d, "k1", source, required=False) or 0.0,
        "k2": _number(d, "k2", source, required=False) or 0.0,
        "defocus_px": _number(d, "defocus_px", source, required=False),
    }
    if "crossing" in d:
        if not isinstance(d["crossing"], str):
            raise CameraFileError(source, f"must be \"+x\" or \"-x\", got {d['crossing']!r}", "crossing")
        kw["crossing"] = d["crossing"]
    if "gravity_mps2" in d:
        kw["gravity_mps2"] = tuple(float(v) for v in _as_matrix(d["gravity_mps2"], (3,), source, "gravity_mps2"))
    if "pose" in d:
        pose = d["pose"]
        if not isinstance(pose, dict):
            raise CameraFileError(source, "must be a table with rotation and translation", "pose")
        extra = set(pose) - {"rotation", "translation"}
        if extra:
            raise CameraFileError(source, "unknown key in [pose]", "pose." + sorted(extra)[0])
        for k in ("rotation", "translation"):
            if k not in pose:
                raise CameraFileError(source, "missing", f"pose.{k}")
        R = _as_matrix(pose["rotation"], (3, 3), source, "pose.rotation")
        t = _as_matrix(pose["translation"], (3,), source, "pose.translation")
        kw["rotation"] = tuple(tuple(float(v) for v in row) for row in R)
        kw["translation_m"] = tuple(float(v) for v in t)
    return LineScanCamera(**kw, source=source)


def _read_toml(path: Path, kind: str) -> dict[str, Any]:
    """The table of the TOML file ``path``, read for a ``kind`` file (``"camera"``, ``"rig"``).

    Raises
    ------
    CameraFileError
        With a one-line message naming the file: not found, unreadable, over
        :data:`MAX_CAMERA_FILE_BYTES`, not UTF-8 text or not valid TOML.
    """
    text = read_small_text(path, MAX_CAMERA_FILE_BYTES, kind, CameraFileError)
    try:
        return tomllib.loads(text)
    except RecursionError:
        raise CameraFileError(str(path), f"not a {kind} file (arrays or tables nested too deeply to read)") from None
    except ValueError as exc:  # TOML's errors, and integers beyond Python's digit limit
        raise CameraFileError(str(path), f"not valid TOML ({exc})") from None


def load_camera(path: str | Path) -> LineScanCamera:
    """Read and validate a camera TOML file (geometry.md).

    Raises
    ------
    CameraFileError
        With a one-line message naming the file and, where it applies, the key.
    """
    path = Path(path)
    return camera_from_dict(_read_toml(path, "camera"), source=str(path))


def save_camera(camera: LineScanCamera, path: str | Path, comment: str | None = None, *, force: bool = False) -> None:
    """Write a camera as geometry.md TOML, whole or not at all, not through a symbolic link unless ``force`` (:func:`ballscan.outputs.atomic_write_text`)."""
    import tomli_w

    text = tomli_w.dumps(camera.to_dict())
    if comment:
        text = "".join(f"# {line}\n" for line in comment.splitlines()) + text
    atomic_write_text(path, text, force=force)


def crop_camera(camera: LineScanCamera, col_start: int, col_stop: int, *, exposure_s: float | None = None) -> LineScanCamera:
    """The camera of sensor pixels ``[col_start, col_stop)`` only.

    The same camera frame and optics; pixel ``j`` of the crop is pixel
    ``col_start + j`` of the sensor, so ``u' = u - col_start`` and the
    principal point moves by ``-col_start`` (pixels). Positions and
    velocities measured with it need no correction.

    Parameters
    ----------
    camera : LineScanCamera
    col_start, col_stop : int
        The crop's sensor pixels, ``0 <= col_start < col_stop <= width``.
    exposure_s : float, optional
        Also set the exposure (s).

    Returns
    -------
    LineScanCamera
        Equal to ``dataclasses.replace(camera, width=..., principal_px=...,
        exposure_s=...)``, made without validating it again: a crop of a
        valid camera is valid (its distortion is monotonic over a part of
        the sensor's range), and the validation (a distortion check on
        257 points) would lie on every stream ball's latency path. An exposure
        outside ``(0, 1 / line_rate_hz]`` or an empty or outside range is
        validated (and refused) as by ``replace``.
    """
    changes: dict[str, Any] = {}
    if not (col_start == 0 and col_stop == camera.width):
        changes.update(width=int(col_stop - col_start), principal_px=camera.principal_px - col_start)
    if exposure_s is not None:
        changes["exposure_s"] = exposure_s
    if not changes:
        return camera
    valid = 0 <= col_start and col_start + 2 <= col_stop <= camera.width
    if exposure_s is not None:
        valid = valid and isinstance(exposure_s, float) and 0.0 < exposure_s <= 1.0 / camera.line_rate_hz
    if not valid:
        return replace(camera, **changes)
    crop = copy.copy(camera)  # no __init__, no validation
    for key, value in changes.items():
        object.__setattr__(crop, key, value)
    return crop
