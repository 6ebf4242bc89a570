"""Synthetic line-scan images of moving balls (the paper's "digital ball").

The renderer is deliberately independent of :mod:`ballscan.model.silhouette`: it
draws the ball by supersampled ray-sphere intersection over each pixel's
area and exposure, so that the analytic edges and the rendered images can
check each other.

Sampling of one pixel ``j`` of line ``i`` (camera frame of geometry.md):

* along the sensor, ``samples_along`` offsets in ``[j - 1/2, j + 1/2]``
  (pixels), each mapped to the undistorted normalised coordinate
  ``n = camera.backproject(u)``;
* across the line, ``samples_across`` ray tilts ``s = x / z`` at the stratum
  midpoints of ``[-1/(2f), 1/(2f)]`` (the pixel's footprint, one pixel
  pitch);
* over time, ``samples_time`` instants at the stratum midpoints of the
  exposure ``[t_i - tau/2, t_i + tau/2]``.

The ray of sample ``(u, s)`` is ``lambda * (s, n, 1)``, ``lambda > 0``; it is
intersected with every ball at the sample's time and the nearest hit wins
(occlusion).  The along-sensor offsets form a multi-jittered ("N-rooks")
pattern: each ``(s, t)`` pair uses the regular grid of ``samples_along``
offsets shifted by its own sub-stratum, so the union of all of a pixel's
offsets is a regular grid of ``samples_along * samples_across *
samples_time`` positions.  An edge that barely moves during the exposure is
then measured to ``1 / (samples_along * samples_across * samples_time)``
pixel instead of ``1 / samples_along``.

Only pixels near a ball are sampled (see :func:`_ball_spans`): pixels a
silhouette may cross get the full pattern, pixels wholly inside a ball a
smaller one (shading only), and the rest of the image is background.  On a
ball's first and last lines (:func:`_cap_lines`) the pixels a silhouette
may cross get ``cap_across x cap_time`` tilts and instants: there the
section grows like the square root of its offset, and a coarse grid biases
the line's coverage (see :class:`RenderSettings`).

The sensor model follows the reference scenes (``noise.model`` in
``/work/shared/scenes/*.truth.json``)::

    DN = black_dn + Poisson(Y * g_j * full_well_e) * white_dn / full_well_e + N(0, read_dn^2)

rounded and clipped to the bit depth, with ``Y`` the linear grey level in
``[0, 1]`` and ``g_j = 1 + prnu_sigma * N(0, 1)`` a gain per sensor column.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from ..outputs import atomic_write_bytes
from ..geometry.camera import LineScanCamera, line_times
from ..errors import GeometryError
from ..geometry.motion import BallMotion

__all__ = [
    "Appearance",
    "SensorNoise",
    "RenderSettings",
    "Rendered",
    "render",
    "apply_sensor",
    "write_image",
    "encode_image",
    "truth_dict",
]

#: Samples (pixels x sub-samples) processed per vectorised batch; bounds memory.
_BATCH_SAMPLES = 1 << 18
#: Mean electron count above which shot noise is drawn from its normal approximation.
_NORMAL_SHOT_ABOVE_E = 1000.0
#: Default direction towards the light (camera frame): up-left of and behind the camera.
_DEFAULT_LIGHT = (-0.35, -0.45, -0.82)


def _unit3(value: Any, name: str) -> tuple[float, float, float]:
    arr = np.asarray(value, dtype=float).reshape(-1)
    if arr.shape != (3,) or not np.all(np.isfinite(arr)):
        raise ValueError(f"{name}: expected 3 finite numbers, got {value!r}")
    norm = float(np.linalg.norm(arr))
    if norm == 0.0:
        raise ValueError(f"{name}: must not be the zero vector")
    arr = arr / norm
    return (float(arr[0]), float(arr[1]), float(arr[2]))


def _check_level(value: float, name: str) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float, np.floating, np.integer)):
        raise ValueError(f"{name}: must be a number in [0, 1], got {value!r}")
    v = float(value)
    if not (0.0 <= v <= 1.0):
        raise ValueError(f"{name}: must be in [0, 1] (linear grey), got {value!r}")
    return v


@dataclass(frozen=True)
class Appearance:
    """How a ball looks: albedo, shading and optional tennis-ball texture.

    Parameters
    ----------
    ball_level : float
        Linear grey level of the ball's surface (felt) in ``[0, 1]``; may be
        brighter or darker than the background.
    shading : bool
        Lambertian shading ``level * (ambient + (1 - ambient) * max(0, N . L))``
        when True; a flat disc of ``ball_level`` (no shading) when False.
    light_dir : tuple of float
        Direction from the ball towards the light, camera frame (normalised
        on construction).
    ambient : float
        Fraction of the level seen on surfaces facing away from the light,
        in ``[0, 1]``.
    texture : {"none", "tennis"}
        ``"tennis"`` draws a seam band along the classic saddle curve
        ``z = k (x^2 - y^2)`` of the ball's body frame.
    seam_level : float
        Linear grey level of the seam (before shading), ``[0, 1]``.
    seam_width_rad : float
        Full angular width of the seam band (radians on the sphere; a 7 mm
        seam on a 33.5 mm tennis ball is about 0.2).
    spin_axis : tuple of float
        Spin axis in the camera frame (normalised on construction).
    spin_rps : float
        Spin rate in revolutions per second (right-handed about ``spin_axis``).
    orientation_seed : int
        Seed of the ball's random initial orientation (body -> camera at
        ``t_c``); the texture is deterministic given this seed.
    """

    ball_level: float = 0.8
    shading: bool = True
    light_dir: tuple[float, float, float] = _DEFAULT_LIGHT
    ambient: float = 0.35
    texture: str = "none"
    seam_level: float = 0.97
    seam_width_rad: float = 0.2
    spin_axis: tuple[float, float, float] = (0.0, 1.0, 0.0)
    spin_rps: float = 0.0
    orientation_seed: int = 0

    def __post_init__(self) -> None:
        object.__setattr__(self, "ball_level", _check_level(self.ball_level, "ball_level"))
        object.__setattr__(self, "seam_level", _check_level(self.seam_level, "seam_level"))
        object.__setattr__(self, "ambient", _check_level(self.ambient, "ambient"))
        object.__setattr__(self, "light_dir", _unit3(self.light_dir, "light_dir"))
        object.__setattr__(self, "spin_axis", _unit3(self.spin_axis, "spin_axis"))
        if self.texture not in ("none", "tennis"):
            raise ValueError(f"texture: expected 'none' or 'tennis', got {self.texture!r}")
        if not (math.isfinite(self.seam_width_rad) and 0.0 < self.seam_width_rad < math.pi):
            raise ValueError(f"seam_width_rad: must be in (0, pi), got {self.seam_width_rad!r}")
        if not math.isfinite(self.spin_rps):
            raise ValueError(f"spin_rps: must be finite, got {self.spin_rps!r}")
        if isinstance(self.orientation_seed, bool) or not isinstance(self.orientation_seed, (int, np.integer)):
            raise ValueError(f"orientation_seed: must be an integer, got {self.orientation_seed!r}")

    @classmethod
    def flat(cls, ball_level: float = 0.8) -> "Appearance":
        """A uniform, unshaded, untextured ball (for geometric tests)."""
        return cls(ball_level=ball_level, shading=False, texture="none")

    def initial_rotation(self) -> np.ndarray:
        """Body -> camera rotation at ``t_c`` (3 x 3), drawn from ``orientation_seed``."""
        rng = np.random.default_rng(self.orientation_seed)
        q = rng.standard_normal(4)
        q /= np.linalg.norm(q)
        w, x, y, z = q
        return np.array(
            [
                [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
            ]
        )


@dataclass(frozen=True)
class SensorNoise:
    """Sensor response and noise (the reference scenes' ``noise.model``).

    ``DN = black_dn + Poisson(Y g_j full_well_e) white_dn / full_well_e + N(0, read_dn^2)``,
    rounded and clipped to ``[0, 2**bits - 1]``; ``g_j = 1 + prnu_sigma N(0, 1)``
    per column.  Pixels with a mean of more than 1000 electrons draw the shot
    and read noise together from the normal distribution of the same mean and
    variance (the Poisson's skewness is then below 0.032; see
    :func:`apply_sensor`).

    Parameters
    ----------
    bits : {8, 12, 16}
        Bit depth; 12-bit data are stored in ``uint16`` as ``0 .. 4095``.
    white_dn : float
        Signal in DN (above black) of linear grey ``Y = 1``.
    black_dn : float
        Black level in DN.
    read_dn : float
        Standard deviation of the Gaussian read noise, DN.
    full_well_e : float or None
        Electrons at ``Y = 1`` (sets the shot noise); ``None`` for no shot noise.
    prnu_sigma : float
        Relative standard deviation of the per-column gain (fixed-pattern).
    """

    bits: int = 8
    white_dn: float = 230.0
    black_dn: float = 6.0
    read_dn: float = 2.0
    full_well_e: float | None = 12000.0
    prnu_sigma: float = 0.008

    def __post_init__(self) -> None:
        if self.bits not in (8, 12, 16) or isinstance(self.bits, bool):
            raise ValueError(f"bits: expected 8, 12 or 16, got {self.bits!r}")
        for name in ("white_dn", "black_dn", "read_dn", "prnu_sigma"):
            v = getattr(self, name)
            if not (isinstance(v, (int, float, np.floating, np.integer)) and math.isfinite(v) and v >= 0):
                raise ValueError(f"{name}: must be a finite number >= 0, got {v!r}")
        if self.white_dn <= 0:
            raise ValueError(f"white_dn: must be positive, got {self.white_dn!r}")
        if self.full_well_e is not None and not (math.isfinite(self.full_well_e) and self.full_well_e > 0):
            raise ValueError(f"full_well_e: must be positive and finite (or None for no shot noise), got {self.full_well_e!r}")

    @classmethod
    def none(cls, bits: int = 16) -> "SensorNoise":
        """Noise-free full-range quantisation: ``DN = round(Y * (2**bits - 1))``."""
        return cls(bits=bits, white_dn=float(2**bits - 1), black_dn=0.0, read_dn=0.0, full_well_e=None, prnu_sigma=0.0)

    @property
    def max_dn(self) -> int:
        """Saturation level of the stored type (``2**bits - 1``)."""
        return 2**self.bits - 1

    @property
    def dtype(self) -> type:
        """``numpy.uint8`` for 8 bits, ``numpy.uint16`` otherwise."""
        return np.uint8 if self.bits == 8 else np.uint16

    @property
    def is_noiseless(self) -> bool:
        return self.read_dn == 0 and self.full_well_e is None and self.prnu_sigma == 0

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready description (the reference scenes' ``noise`` keys)."""
        return {
            "bits": self.bits,
            "white_dn": self.white_dn,
            "black_dn": self.black_dn,
            "read_dn": self.read_dn,
            "full_well_e": self.full_well_e,
            "prnu_sigma": self.prnu_sigma,
            "model": "DN = black_dn + Poisson(Y*g_j*full_well_e)*white_dn/full_well_e + N(0, read_dn^2), "
            "rounded and clipped; g_j = 1 + prnu_sigma*N(0,1) per column",
        }


@dataclass(frozen=True)
class RenderSettings:
    """Supersampling of each pixel.

    Pixels that a ball's silhouette may cross ("edge" pixels) use the full
    pattern ``samples_along x samples_across x samples_time``; coverage and
    hence the silhouette come from them.  Pixels proven to lie wholly inside
    a ball for every sample ("interior" pixels) only need the shading and
    texture integrated, which are smooth or motion-blurred, so they use the
    smaller ``interior_*`` pattern.

    Parameters
    ----------
    samples_along : int
        Sub-samples along the sensor within an edge pixel.  The default 16
        keeps area-based edges within about 0.01 px of the exact average
        (8 gives about 0.025 px at worst where edges move during the
        exposure).
    samples_across : int
        Ray tilts across the line within the pixel's footprint ``|s| <= 1/(2f)``.
    samples_time : int
        Instants within the exposure window.
    interior_along, interior_across, interior_time : int
        The same for interior pixels.
    cap_across, cap_time : int
        Tilts and instants of the edge pixels on a ball's first and last
        lines (its caps: lines on which a sample's section plane lies more
        than ``0.9 R`` from the ball's centre).  There the section grows
        like the square root of the plane's offset, which both the tilt and
        the time shift: with the 4 x 8 (tilt x time) grid of the other
        lines a cap line's summed coverage is up to 0.066 px off the
        continuous exposure (three times the area noise of a typical end
        line);
        with 16 x 16 at most 0.01 px (measured against 32 x 256 on the
        bench ball of ``benchmarks/bench_fit.py``, at 0 and 30 degrees).
    sampling_seed : int
        Seed of the permutation that assigns the along-sensor sub-stratum
        shifts to the ``(across, time)`` pairs (deterministic; independent
        of the noise seed).
    """

    samples_along: int = 16
    samples_across: int = 4
    samples_time: int = 8
    interior_along: int = 4
    interior_across: int = 1
    interior_time: int = 4
    cap_across: int = 16
    cap_time: int = 16
    sampling_seed: int = 0

    def __post_init__(self) -> None:
        for name in ("samples_along", "samples_across", "samples_time", "interior_along", "interior_across", "interior_time", "cap_across", "cap_time"):
            v = getattr(self, name)
            if isinstance(v, bool) or not isinstance(v, (int, np.integer)) or not (1 <= v <= 256):
                raise ValueError(f"{name}: must be an integer in 1..256, got {v!r}")
        if isinstance(self.sampling_seed, bool) or not isinstance(self.sampling_seed, (int, np.integer)):
            raise ValueError(f"sampling_seed: must be an integer, got {self.sampling_seed!r}")

    @property
    def samples_per_pixel(self) -> int:
        """Samples of an edge pixel."""
        return self.samples_along * self.samples_across * self.samples_time


@dataclass(frozen=True, eq=False)
class Rendered:
    """A rendered line-scan image and its ground truth.

    Attributes
    ----------
    image : ndarray, shape (n_lines, width)
        Stored values (DN) after the sensor model: ``uint8`` for 8 bits,
        ``uint16`` for 12 (``0 .. 4095``) and 16 bits.
    clean : ndarray of float64, shape (n_lines, width)
        Noise-free linear grey level in ``[0, 1]`` (pixel average).
    coverage : ndarray of float64, shape (n_lines, width)
        Fraction of each pixel's samples that hit a ball (0..1).
    balls : tuple of BallMotion
        The true motions, in the order given.
    appearances : tuple of Appearance
    camera : LineScanCamera
    t_lines_s : ndarray, shape (n_lines,)
        Centre time of each line, seconds.
    noise : SensorNoise
        The sensor model that made ``image``.
    column_gain : ndarray, shape (width,)
        The fixed-pattern gains ``g_j`` used (ones without PRNU).
    background_level : float
    settings : RenderSettings
    """

    image: np.ndarray
    clean: np.ndarray
    coverage: np.ndarray
    balls: tuple[BallMotion, ...]
    appearances: tuple[Appearance, ...]
    camera: LineScanCamera
    t_lines_s: np.ndarray
    noise: SensorNoise
    column_gain: np.ndarray
    background_level: float
    settings: RenderSettings = field(default_factory=RenderSettings)

    def truth_dict(self) -> dict[str, Any]:
        """geometry.md truth JSON content (see :func:`truth_dict`)."""
        return truth_dict(self.balls)


# ------------------------------------------------------------------ sampling


@dataclass(frozen=True, eq=False)
class _Pattern:
    """Sub-samples of one pixel: along-sensor offsets (M, A) in pixels, tilts (M,), time offsets (M,) in s.

    ``level_pairs`` (M,) of bool, when set, marks the (tilt, time) pairs at
    which a textured surface is evaluated; the pixel's other hit samples
    take the mean of those (the coverage still counts every sample).
    """

    offsets_px: np.ndarray
    tilt: np.ndarray
    dt_s: np.ndarray
    level_pairs: np.ndarray | None = None


def _sample_pattern(along: int, across: int, times: int, seed: int, f_px: float, tau_s: float, level_stride: int = 1) -> _Pattern:
    """Stratified pattern; ``M = across * times`` indexes the (tilt, time) pairs.

    ``level_stride > 1`` marks every ``level_stride``-th diagonal of the
    (tilt, time) grid as the pairs a texture is evaluated at (all tilts and
    all instants among them).
    """
    M = across * times
    s_idx, t_idx = np.divmod(np.arange(M), times)
    tilt = ((s_idx + 0.5) / across - 0.5) / f_px
    dt = ((t_idx + 0.5) / times - 0.5) * tau_s
    # N-rooks: pair m's along-sensor grid is shifted by its own sub-stratum perm[m]/M,
    # permuted so the shift is uncorrelated with tilt and time.  The union of a
    # pixel's offsets is then a regular grid of M*A positions.
    perm = np.random.default_rng(seed).permutation(M)
    offsets = -0.5 + (np.arange(along)[None, :] + (perm[:, None] + 0.5) / M) / along
    level_pairs = None if level_stride <= 1 else (s_idx + t_idx) % level_stride == 0
    return _Pattern(offsets, tilt, dt, level_pairs)


def _ball_spans(
    camera: LineScanCamera,
    motion: BallMotion,
    t_lines: np.ndarray,
    pattern: _Pattern,
    n_sensor: tuple[float, float],
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Columns a ball may touch and columns it surely covers, per line.

    Returns ``(outer_lo, outer_hi, inner_lo, inner_hi)`` (inclusive column
    indices; ``lo > hi`` means none).  Every sample of the pattern that hits
    the ball lies in an outer pixel; every sample of an inner pixel hits it.

    For the sample plane ``x = s z`` at time ``t``, the rays ``(s, n, 1)``
    meet the sphere where the ray-sphere discriminant is non-negative,

        (b_s + n c_y)^2 - (1 + s^2 + n^2) (|C|^2 - R^2) >= 0,   b_s = s c_x + c_z,

    a quadratic in ``n`` whose two roots bound the hit rays of that plane.
    This only decides which pixels are supersampled with which pattern; the
    pixel values themselves come from intersecting every sample ray.
    """
    W = camera.width
    R = motion.radius_m
    c = motion.centre(t_lines[:, None] + pattern.dt_s[None, :])  # (L, M, 3)
    cx, cy, cz = c[..., 0], c[..., 1], c[..., 2]
    s = pattern.tilt[None, :]
    bs = s * cx + cz
    cc = cx * cx + cy * cy + cz * cz - R * R
    alpha = R * R - cx * cx - cz * cz  # coefficient of n^2; < 0 when the ball is in front
    beta = bs * cy
    gamma = bs * bs - (1.0 + s * s) * cc
    delta = beta * beta - alpha * gamma
    scale = beta * beta + np.abs(alpha * gamma)
    in_front = cz > R * (1.0 + 1e-9)
    touch = in_front & (delta > -1e-9 * scale)  # slack: a grazing sample may still hit
    # A ball reaching z <= R (and not wholly behind the camera): rays at any angle may hit.
    anywhere = (~in_front) & (cz + R > 0) & (np.abs(cx - s * cz) <= R * np.sqrt(1.0 + s * s) * (1.0 + 1e-9))

    root = np.sqrt(np.maximum(delta, 0.0))
    neg_alpha = np.where(in_front, -alpha, 1.0)
    n_lo = (beta - root) / neg_alpha
    n_hi = (beta + root) / neg_alpha
    # Distortion is only monotonic near the sensor: clip before projecting.
    u_lo = camera.project_normalised(np.clip(n_lo, *n_sensor))
    u_hi = camera.project_normalised(np.clip(n_hi, *n_sensor))

    big = float(W + 10)
    # Pixel j spans [j - 1/2, j + 1/2]: it holds a hit sample only if j >= u_lo - 1/2 and
    # j <= u_hi + 1/2; floor/ceil keep a rounding-safe extra pixel where these are near integers.
    outer_lo = np.floor(np.where(touch, u_lo, big).min(axis=1) - 0.5).astype(np.int64)
    outer_hi = np.ceil(np.where(touch, u_hi, -big).max(axis=1) + 0.5).astype(np.int64)
    eps = 1e-6  # px: keeps a pixel whose end coincides with an edge out of the interior
    full = np.all(in_front & (delta > 0), axis=1)
    inner_lo = np.ceil(u_lo.max(axis=1) + 0.5 + eps).astype(np.int64)
    inner_hi = np.floor(u_hi.min(axis=1) - 0.5 - eps).astype(np.int64)
    inner_lo = np.where(full, inner_lo, W)
    inner_hi = np.where(full, inner_hi, -1)
    wide = np.any(anywhere, axis=1)
    outer_lo = np.where(wide, 0, outer_lo)
    outer_hi = np.where(wide, W - 1, outer_hi)
    inner_lo = np.where(wide, W, inner_lo)
    inner_hi = np.where(wide, -1, inner_hi)
    # Clip to -1..W rather than 0..W-1 so that empty ranges stay empty.
    return tuple(np.clip(a, -1, W) for a in (outer_lo, outer_hi, inner_lo, inner_hi))  # type: ignore[return-value]


def _cap_lines(camera: LineScanCamera, motion: BallMotion, t_lines: np.ndarray, reach: float = 0.9) -> np.ndarray:
    """Lines on which the ball is seen and some sample's section plane lies more than ``reach * R`` from its centre.

    The plane of tilt ``s`` meets the ball at distance ``|c_x - s c_z|``
    (over ``sqrt(1 + s^2)``) from its centre; over the exposure ``c_x``
    moves by ``|v_x| tau / 2`` either way and over the pixel's height ``s
    c_z`` by ``c_z / (2 f)``: the planes of a line lie between ``|c_x| - w``
    and ``|c_x| + w`` from the centre, ``w`` the sum of the two.
    """
    c = motion.centre(t_lines)
    vx = np.abs(motion.velocity_at(t_lines)[:, 0])
    w = vx * camera.exposure / 2.0 + np.abs(c[:, 2]) / (2.0 * camera.focal_px)
    near, far = np.abs(c[:, 0]) - w, np.abs(c[:, 0]) + w
    return (far > reach * motion.radius_m) & (near < motion.radius_m)


def _paint(lo: np.ndarray, hi: np.ndarray, W: int) -> np.ndarray:
    """Boolean (L, W) mask of the column range ``lo..hi`` of every line."""
    L = lo.size
    lo_c = np.clip(lo, 0, W)
    hi_c = np.clip(hi, -1, W - 1)
    rows = np.flatnonzero(hi_c >= lo_c)
    diff = np.zeros((L, W + 1), dtype=np.int32)
    diff[rows, lo_c[rows]] += 1
    diff[rows, hi_c[rows] + 1] -= 1
    return np.cumsum(diff[:, :W], axis=1) > 0


# ------------------------------------------------------------------ shading


def _rotate(v: np.ndarray, axis: np.ndarray, angle: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Rodrigues rotation of the vectors ``v = (vx, vy, vz)`` about a unit ``axis`` by ``angle`` (rad)."""
    vx, vy, vz = v
    kx, ky, kz = axis
    cos, sin = np.cos(angle), np.sin(angle)
    kdotv = (kx * vx + ky * vy + kz * vz) * (1.0 - cos)
    rx = vx * cos + (ky * vz - kz * vy) * sin + kx * kdotv
    ry = vy * cos + (kz * vx - kx * vz) * sin + ky * kdotv
    rz = vz * cos + (kx * vy - ky * vx) * sin + kz * kdotv
    return rx, ry, rz


#: Saddle parameter of the seam curve z = k (x^2 - y^2): it reaches about 0.8 rad of
#: latitude, like a tennis ball's seam.
_SEAM_SADDLE_K = 2.5


def _surface_level(
    app: Appearance,
    motion: BallMotion,
    rot0: np.ndarray,
    normal: tuple[np.ndarray, np.ndarray, np.ndarray],
    t: np.ndarray,
) -> np.ndarray:
    """Linear grey level of surface points with camera-frame unit normals ``normal`` at times ``t``."""
    nx, ny, nz = normal
    level = np.full(np.broadcast_shapes(nx.shape, t.shape), app.ball_level)
    if app.texture == "tennis":
        # Camera -> body: undo the spin since t_c, then the initial orientation.
        angle = -2.0 * math.pi * app.spin_rps * (t - motion.t_c_s)
        if app.spin_rps != 0.0:
            nx, ny, nz = _rotate((nx, ny, nz), np.asarray(app.spin_axis), angle)
        bx = rot0[0, 0] * nx + rot0[1, 0] * ny + rot0[2, 0] * nz
        by = rot0[0, 1] * nx + rot0[1, 1] * ny + rot0[2, 1] * nz
        bz = rot0[0, 2] * nx + rot0[1, 2] * ny + rot0[2, 2] * nz
        k = _SEAM_SADDLE_K
        F = bz - k * (bx * bx - by * by)
        # First-order angular distance to the curve F = 0: |F| / |tangential grad F|.
        gx, gy, gz = -2.0 * k * bx, 2.0 * k * by, np.ones_like(bz)
        gdotn = gx * bx + gy * by + gz * bz
        gt2 = (gx - gdotn * bx) ** 2 + (gy - gdotn * by) ** 2 + (gz - gdotn * bz) ** 2
        seam = F * F < (0.5 * app.seam_width_rad) ** 2 * gt2
        level = np.where(seam, app.seam_level, level)
        nx, ny, nz = normal
    if app.shading:
        lx, ly, lz = app.light_dir
        lam = np.maximum(nx * lx + ny * ly + nz * lz, 0.0)
        level = level * (app.ambient + (1.0 - app.ambient) * lam)
    return level


# ------------------------------------------------------------------- render


def _normalise_balls(
    balls: Sequence[tuple[BallMotion, Appearance]] | Sequence[BallMotion] | BallMotion,
) -> tuple[tuple[BallMotion, ...], tuple[Appearance, ...]]:
    if isinstance(balls, BallMotion):
        return (balls,), (Appearance(),)
    if isinstance(balls, tuple) and len(balls) == 2 and isinstance(balls[0], BallMotion) and isinstance(balls[1], Appearance):
        return (balls[0],), (balls[1],)  # one (motion, appearance) pair
    motions, apps = [], []
    for k, item in enumerate(balls):
        if isinstance(item, BallMotion):
            motions.append(item)
            apps.append(Appearance())
        elif isinstance(item, tuple) and len(item) == 2 and isinstance(item[0], BallMotion) and isinstance(item[1], Appearance):
            motions.append(item[0])
            apps.append(item[1])
        else:
            raise ValueError(f"balls[{k}]: expected a BallMotion or a (BallMotion, Appearance) pair, got {item!r}")
    return tuple(motions), tuple(apps)


def render(
    camera: LineScanCamera,
    balls: Sequence[tuple[BallMotion, Appearance]] | Sequence[BallMotion] | BallMotion,
    n_lines: int,
    *,
    background_level: float = 0.1,
    noise: SensorNoise | str | None = SensorNoise(),
    seed: int | np.random.Generator | None = 0,
    settings: RenderSettings = RenderSettings(),
    t_lines_s: np.ndarray | None = None,
) -> Rendered:
    """Render a line-scan image of one or several moving balls.

    Parameters
    ----------
    camera : LineScanCamera
        Intrinsics, distortion, line rate and exposure (``camera.exposure``).
    balls : BallMotion, (BallMotion, Appearance), or a sequence of either
        The balls (camera frame); a bare motion gets the default
        :class:`Appearance`.  Where balls overlap, the nearer one along each
        sample ray is seen.
    n_lines : int
        Number of scan lines (image rows).
    background_level : float
        Linear grey level of the (uniform) background, ``[0, 1]``.
    noise : SensorNoise, None or "none"
        Sensor model; ``None`` or ``"none"`` means :meth:`SensorNoise.none`
        (noise-free 16-bit).
    seed : int, numpy.random.Generator or None
        Seed of the sensor noise (same seed -> identical image; ``None``
        draws fresh entropy).  The clean image does not depend on it.
    settings : RenderSettings
        Supersampling.
    t_lines_s : array_like or None
        Centre time of each line (seconds, strictly increasing); default
        ``i / line_rate_hz``.

    Returns
    -------
    Rendered
        The stored image, the clean linear image, the coverage image and the
        truth.

    Raises
    ------
    ValueError
        On invalid arguments.
    GeometryError
        If the projection centre is inside a ball at some sample time.
    """
    if isinstance(n_lines, bool) or not isinstance(n_lines, (int, np.integer)) or n_lines < 1:
        raise ValueError(f"n_lines: must be a positive integer, got {n_lines!r}")
    if not isinstance(camera, LineScanCamera):
        raise ValueError(f"camera: expected a LineScanCamera, got {type(camera).__name__}")
    if not isinstance(settings, RenderSettings):
        raise ValueError(f"settings: expected RenderSettings, got {type(settings).__name__}")
    background_level = _check_level(background_level, "background_level")
    if noise is None or (isinstance(noise, str) and noise == "none"):
        noise = SensorNoise.none()
    elif not isinstance(noise, SensorNoise):
        raise ValueError(f"noise: expected a SensorNoise, None or 'none', got {noise!r}")
    motions, apps = _normalise_balls(balls)
    t_lines = line_times(camera, int(n_lines), t_lines_s)

    clean, coverage = _render_linear(camera, motions, apps, t_lines, background_level, settings)
    image, gain = apply_sensor(clean, noise, seed)
    return Rendered(
        image=image,
        clean=clean,
        coverage=coverage,
        balls=motions,
        appearances=apps,
        camera=camera,
        t_lines_s=t_lines,
        noise=noise,
        column_gain=gain,
        background_level=background_level,
        settings=settings,
    )


def _render_linear(
    camera: LineScanCamera,
    motions: tuple[BallMotion, ...],
    apps: tuple[Appearance, ...],
    t_lines: np.ndarray,
    background: float,
    settings: RenderSettings,
) -> tuple[np.ndarray, np.ndarray]:
    """Clean linear image and coverage image, both (n_lines, width) float64."""
    W = camera.width
    L = t_lines.size
    clean = np.full((L, W), background)
    coverage = np.zeros((L, W))
    if not motions:
        return clean, coverage

    f, tau = camera.focal_px, camera.exposure
    st = settings
    edge_pat = _sample_pattern(st.samples_along, st.samples_across, st.samples_time, st.sampling_seed, f, tau)
    inner_pat = _sample_pattern(st.interior_along, st.interior_across, st.interior_time, st.sampling_seed + 1, f, tau)
    # the cap pattern is for the coverage: a texture there is evaluated at
    # about as many pairs as on the other edge pixels (it costs 2x the
    # render of a textured ball otherwise)
    level_stride = max(1, (st.cap_across * st.cap_time) // (st.samples_across * st.samples_time))
    cap_pat = _sample_pattern(st.samples_along, st.cap_across, st.cap_time, st.sampling_seed + 2, f, tau, level_stride)
    # Normalised coordinates a little beyond the sensor's ends bound every sample ray.
    n_sensor = (float(camera.backproject(-1.0)), float(camera.backproject(float(W))))

    instants = np.r_[edge_pat.dt_s, cap_pat.dt_s]
    for mo in motions:
        c = mo.centre(t_lines[:, None] + instants[None, :])
        if np.any(np.einsum("lmk,lmk->lm", c, c) <= mo.radius_m**2):
            raise GeometryError("the projection centre is inside a ball during the image: cannot render")

    # the lines any ball's cap is on get the cap pattern, and which pixels a
    # ball may touch or surely covers there follows from its samples
    cap_lines = np.zeros(L, dtype=bool)
    for mo in motions:
        cap_lines |= _cap_lines(camera, mo, t_lines)
    spans = []
    for mo in motions:
        sp = [a.copy() for a in _ball_spans(camera, mo, t_lines, edge_pat, n_sensor)]
        if cap_lines.any():
            for a, b in zip(sp, _ball_spans(camera, mo, t_lines[cap_lines], cap_pat, n_sensor)):
                a[cap_lines] = b
        spans.append(tuple(sp))
    active = np.zeros(L, dtype=bool)
    for olo, ohi, _, _ in spans:
        active |= ohi >= olo
    lines = np.flatnonzero(active)
    if lines.size == 0:
        return clean, coverage
    l0, l1 = int(lines[0]), int(lines[-1]) + 1
    edge = np.zeros((l1 - l0, W), dtype=bool)
    inner = np.zeros((l1 - l0, W), dtype=bool)
    for olo, ohi, ilo, ihi in spans:
        ball_inner = _paint(ilo[l0:l1], ihi[l0:l1], W)
        edge |= _paint(olo[l0:l1], ohi[l0:l1], W) & ~ball_inner
        inner |= ball_inner
    inner &= ~edge  # another ball's silhouette may cross this ball's interior
    cap = edge & cap_lines[l0:l1, None]
    edge &= ~cap

    rot0 = [app.initial_rotation() for app in apps]
    for mask, pat in ((edge, edge_pat), (cap, cap_pat), (inner, inner_pat)):
        pl, pc = np.nonzero(mask)
        if pl.size == 0:
            continue
        pl = pl + l0
        mean_level, cov = _sample_pixels(camera, motions, apps, rot0, t_lines, pl, pc, pat, background)
        clean[pl, pc] = mean_level
        coverage[pl, pc] = cov
    return clean, coverage


def _sample_pixels(
    camera: LineScanCamera,
    motions: tuple[BallMotion, ...],
    apps: tuple[Appearance, ...],
    rot0: list[np.ndarray],
    t_lines: np.ndarray,
    pix_line: np.ndarray,
    pix_col: np.ndarray,
    pat: _Pattern,
    background: float,
) -> tuple[np.ndarray, np.ndarray]:
    """Mean level and hit fraction of the pixels ``(pix_line, pix_col)`` over the pattern's samples."""
    M, A = pat.offsets_px.shape
    # n of every sub-sample position of the columns in use (distortion inverted once each).
    cols = np.unique(pix_col)
    n_table = camera.backproject(cols.astype(float)[:, None, None] + pat.offsets_px[None, :, :])
    col_index = np.searchsorted(cols, pix_col)
    used = np.unique(pix_line)
    row_of = np.zeros(t_lines.size, dtype=np.int64)
    row_of[used] = np.arange(used.size)
    t_samp = t_lines[used][:, None] + pat.dt_s[None, :]  # (lines used, M)
    centres = [mo.centre(t_samp) for mo in motions]

    npix = pix_line.size
    batch = max(1, _BATCH_SAMPLES // (M * A))
    sum_level = np.empty(npix)
    n_hit = np.empty(npix)
    s = pat.tilt[None, :, None]  # (1, M, 1)
    for b0 in range(0, npix, batch):
        rows = row_of[pix_line[b0 : b0 + batch]]
        n = n_table[col_index[b0 : b0 + batch]]  # (K, M, A)
        t = t_samp[rows][:, :, None]  # (K, M, 1)
        a2 = 1.0 + s * s + n * n
        best = np.full(n.shape, np.inf)
        level = np.full(n.shape, background)
        for motion, app, r0, cen in zip(motions, apps, rot0, centres):
            R = motion.radius_m
            C = cen[rows][:, :, None, :]  # (K, M, 1, 3)
            cx, cy, cz = C[..., 0], C[..., 1], C[..., 2]
            # |lam d - C|^2 = R^2 with d = (s, n, 1): lam^2 |d|^2 - 2 lam (d.C) + |C|^2 - R^2 = 0
            bb = s * cx + n * cy + cz
            cc = cx * cx + cy * cy + cz * cz - R * R  # > 0: camera outside (checked by the caller)
            disc = bb * bb - a2 * cc
            hit = (disc >= 0.0) & (bb > 0.0)  # both roots share the sign of bb; keep those in front
            if not np.any(hit):
                continue
            lam = (bb - np.sqrt(np.maximum(disc, 0.0))) / a2  # nearest hit: depth z of the point
            nearer = hit & (lam < best)
            best = np.where(nearer, lam, best)
            if app.texture != "none":
                # The texture is costly: evaluate it only on the samples this ball wins
                # (and of those, on the pattern's level pairs, see _Pattern).
                shape = nearer.shape

                def surface(mask):
                    sel = np.nonzero(mask)
                    lam_h = lam[sel]
                    s_h = np.broadcast_to(s, shape)[sel]
                    cx_h, cy_h, cz_h = (np.broadcast_to(v, shape)[sel] for v in (cx, cy, cz))
                    normal = ((lam_h * s_h - cx_h) / R, (lam_h * n[sel] - cy_h) / R, (lam_h - cz_h) / R)
                    level[sel] = _surface_level(app, motion, r0, normal, np.broadcast_to(t, shape)[sel])

                if pat.level_pairs is None:
                    surface(nearer)
                else:
                    at = nearer & pat.level_pairs[None, :, None]
                    surface(at)
                    n_at = at.sum(axis=(1, 2))
                    mean_at = np.where(at, level, 0.0).sum(axis=(1, 2)) / np.maximum(n_at, 1)
                    rest = nearer & ~at
                    fill = rest & (n_at > 0)[:, None, None]
                    level[fill] = np.broadcast_to(mean_at[:, None, None], shape)[fill]
                    # a pixel the ball touches at none of the level pairs: all its samples
                    surface(rest & ~fill)
            elif app.shading:
                normal = ((lam * s - cx) / R, (lam * n - cy) / R, (lam - cz) / R)
                level = np.where(nearer, _surface_level(app, motion, r0, normal, t), level)
            else:
                level[nearer] = app.ball_level
        sum_level[b0 : b0 + batch] = level.sum(axis=(1, 2))
        n_hit[b0 : b0 + batch] = np.isfinite(best).sum(axis=(1, 2))
    spp = M * A
    return sum_level / spp, n_hit / spp


# ------------------------------------------------------------------- sensor


def apply_sensor(
    clean: np.ndarray,
    noise: SensorNoise,
    seed: int | np.random.Generator | None = 0,
) -> tuple[np.ndarray, np.ndarray]:
    """Turn a linear image into stored DN through the sensor model.

    Parameters
    ----------
    clean : ndarray, shape (n_lines, width)
        Linear grey levels, nominally in ``[0, 1]``.
    noise : SensorNoise
    seed : int, numpy.random.Generator or None
        Noise seed; the column gains, shot noise and read noise are drawn in
        that order from one generator.

    Returns
    -------
    image : ndarray of ``noise.dtype``
        Rounded and clipped DN.
    column_gain : ndarray, shape (width,)
        The per-column gains ``g_j`` used.
    """
    if not isinstance(noise, SensorNoise):
        raise ValueError(f"noise: expected a SensorNoise, got {noise!r}")
    clean = np.asarray(clean, dtype=float)
    if clean.ndim != 2:
        raise ValueError(f"clean: expected a 2-D image, got shape {clean.shape}")
    rng = seed if isinstance(seed, np.random.Generator) else np.random.default_rng(seed)
    W = clean.shape[1]
    gain = np.ones(W)
    if noise.prnu_sigma > 0:
        gain = 1.0 + noise.prnu_sigma * rng.standard_normal(W)
    signal = np.clip(clean, 0.0, None) * gain[None, :]
    if noise.full_well_e is None:
        dn = signal * noise.white_dn + noise.black_dn
        if noise.read_dn > 0:
            dn = dn + rng.normal(0.0, noise.read_dn, size=dn.shape)
    else:
        # Exact Poisson below _NORMAL_SHOT_ABOVE_E electrons; above it, shot and read noise
        # are one normal draw of the same mean and variance (4x faster; the Poisson's
        # skewness 1/sqrt(lam) < 0.032 there is invisible after scaling to DN and rounding).
        dn_per_e = noise.white_dn / noise.full_well_e
        lam = signal * noise.full_well_e
        z = rng.standard_normal(lam.shape)
        dn = noise.black_dn + dn_per_e * lam + np.sqrt(dn_per_e**2 * lam + noise.read_dn**2) * z
        low = lam < _NORMAL_SHOT_ABOVE_E
        if np.any(low):
            electrons = rng.poisson(lam[low])
            dn[low] = noise.black_dn + dn_per_e * electrons + noise.read_dn * z[low]
    image = np.clip(np.rint(dn), 0, noise.max_dn).astype(noise.dtype)
    return image, gain


# ---------------------------------------------------------------------- I/O


def truth_dict(balls: Sequence[BallMotion]) -> dict[str, Any]:
    """geometry.md truth JSON content: one ball's keys, or ``{"balls": [...]}`` sorted by ``t_c_s``."""
    balls = list(balls)
    if not balls:
        return {"balls": []}
    if len(balls) == 1:
        return balls[0].to_dict()
    return {"balls": [b.to_dict() for b in sorted(balls, key=lambda b: b.t_c_s)]}


def write_image(path: str | Path, image: np.ndarray, *, force: bool = False) -> None:
    """Write a stored image as greyscale PNG (``uint8`` or 16-bit ``uint16``), or TIFF.

    The format follows the file's extension: ``.png`` (8- or 16-bit grey,
    written with Pillow) or ``.tif`` / ``.tiff`` (written with tifffile).
    12-bit data stay ``0 .. 4095`` in the 16-bit file (geometry.md "Images").
    The file is written whole or not at all, and not through a symbolic
    link unless ``force`` (:func:`ballscan.outputs.atomic_write_bytes`).

    Raises
    ------
    ValueError
        If ``image`` is not a 2-D ``uint8`` or ``uint16`` array, or the
        extension is none of those.
    ballscan.outputs.OutputFileError
        ``path`` is a symbolic link (without ``force``) or cannot be written.
    """
    path = Path(path)
    atomic_write_bytes(path, encode_image(image, path.suffix), force=force)


def encode_image(image: np.ndarray, suffix: str = ".png") -> bytes:
    """The bytes of :func:`write_image`'s file for a file name ending in ``suffix`` (``.png``, ``.tif``, ``.tiff``)."""
    import io

    arr = np.asarray(image)
    if arr.ndim != 2 or arr.dtype not in (np.uint8, np.uint16):
        raise ValueError(f"image: expected a 2-D uint8 or uint16 array, got {arr.dtype} of shape {arr.shape}")
    ext = suffix.lower()
    buf = io.BytesIO()
    if ext in (".tif", ".tiff"):
        import tifffile

        tifffile.imwrite(buf, arr, photometric="minisblack")
        return buf.getvalue()
    if ext != ".png":
        raise ValueError(f"image path: expected a .png, .tif or .tiff file name, got {suffix!r}")
    from PIL import Image

    height, width = arr.shape
    if arr.dtype == np.uint8:
        im = Image.frombytes("L", (width, height), np.ascontiguousarray(arr).tobytes())
    else:
        # Pillow's 16-bit grey mode is little-endian "I;16", saved as a 16-bit grey PNG
        im = Image.frombytes("I;16", (width, height), arr.astype("<u2").tobytes())
    im.save(buf, format="PNG")
    return buf.getvalue()
