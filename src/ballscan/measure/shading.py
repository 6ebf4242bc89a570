"""Lambertian shading of the ball, for the edges' limb brightness.

A shaded ball is darker or brighter at its limb than one or two pixels
inside it, and the brightness changes fastest right at the limb: for a
Lambertian sphere lit from the camera's side the brightness at a distance
``d`` inside the limb grows like ``sqrt(d)`` (the surface turns towards the
camera), so a level measured a few pixels inside and extrapolated linearly
still overestimates the limb, and the local-area edge (:mod:`ballscan.measure.edges`)
comes out biased inwards by a few hundredths of a pixel, on one side more than
on the other and changing along the ball's passage: the pattern the depth
velocity is read from.

This module fits one shading law to the ball's interior pixels,

    I = A + max(0, n . b)        (DN),

``n`` the unit surface normal seen by the pixel (ray through the pixel
centre, line centre time, a rough motion: the key-point guess), ``A`` the ambient level
and ``b`` the light's direction times its diffuse strength, robustly (Huber
weights: seams and texture are outliers).  :func:`limb_profile` turns it into
the normalised brightness ``polarity (I - background) / contrast`` of the
ball's surface at any sensor position of any line, which
:func:`ballscan.measure.edges.measure_edges` uses only as a *shape*: the ratio of the
mean brightness over the covered part of an edge pixel to the mean over the
level run (the local level itself still comes from the pixels, so texture and
albedo stay local).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
import numpy as np

from ..compiled import as_arg
from ._shading_kernels import chord_rows, interior_normals, level_scatter, limb_values, level_spans, line_level_sums, shading_fit, unique_lines
from ..geometry.camera import LineScanCamera
from .edges import EdgeMeasurements
from ..errors import GeometryError
from ..model.averaged import averaged_model
from ..model.blur import ALONG_NODES, blur_diameter, semicircle_nodes
from ..model.pixels import pixel_coverage
from ..geometry.motion import BallMotion

__all__ = ["LimbProfile", "ShadingModel", "ball_limb", "fit_shading", "limb_profile", "shade_profile", "surface_normals"]


# a last reweighting round whose robust scale is this many times the best
# round's has diverged (see fit_shading)
_DIVERGED = 1.5
# the fitted light must lower the interior's robust scale by more than this
# fraction below the flat law's (see fit_shading)
_FLAT_TOL = 0.01


@dataclass(frozen=True)
class ShadingModel:
    """``I = ambient_dn + max(0, n . light_dn)`` fitted to a ball's interior.

    Attributes
    ----------
    ambient_dn : float
        Brightness of surfaces facing away from the light, DN.
    light_dn : tuple of float
        Light direction (camera frame, from the ball towards the light)
        times the diffuse brightness, DN.
    residual_rms_dn : float
        Robust scale (1.4826 x the median absolute deviation) of the interior
        pixels about the law, DN (texture, noise).
    n_pixels : int
        Interior pixels used.
    """

    ambient_dn: float
    light_dn: tuple[float, float, float]
    residual_rms_dn: float
    n_pixels: int


def surface_normals(
    camera: LineScanCamera, motion: BallMotion, t_s: np.ndarray, u_px: np.ndarray, h_px: np.ndarray | float = 0.0
) -> tuple[np.ndarray, np.ndarray]:
    """Unit normals of the sphere where the rays through ``u_px`` meet it.

    Parameters
    ----------
    camera : LineScanCamera
    motion : BallMotion
    t_s, u_px : ndarray
        Times (s) and sensor positions (pixels), broadcast together.
    h_px : ndarray or float
        Position across the line within the pixel's height, pixels (0: the
        viewing plane; the pixel spans -1/2 .. 1/2), broadcast too.

    Returns
    -------
    hit : ndarray of bool
        Whether the ray meets the sphere.
    normals : ndarray (..., 3)
        Outward unit normals at the first intersection (where ``hit``; the
        closest point of the ray otherwise).

    See Also
    --------
    ballscan.measure._shading_kernels.limb_values : the same rays, compiled, for the limb profile.
    ballscan.measure._shading_kernels.interior_normals : the same normals, compiled, for :func:`fit_shading`.
    """
    n_u = camera.backproject(np.asarray(u_px, dtype=float))
    h = np.asarray(h_px, dtype=float) / camera.focal_px
    inv = 1.0 / np.sqrt(h * h + n_u * n_u + 1.0)
    dx, dy, dz = h * inv, n_u * inv, inv
    c = motion.centre(np.asarray(t_s, dtype=float))
    cx, cy, cz = c[..., 0], c[..., 1], c[..., 2]
    # the ray's parameter at the centre's foot, and the first intersection
    dc = dx * cx + dy * cy + dz * cz
    disc = dc * dc - (cx * cx + cy * cy + cz * cz) + motion.radius_m**2
    hit = disc >= 0.0
    s = dc - np.sqrt(np.maximum(disc, 0.0))
    nx, ny, nz = s * dx - cx, s * dy - cy, s * dz - cz
    a = 1.0 / np.maximum(np.sqrt(nx * nx + ny * ny + nz * nz), 1e-12)
    normals = np.stack(np.broadcast_arrays(nx * a, ny * a, nz * a), axis=-1)
    return np.broadcast_to(hit, normals.shape[:-1]), normals


def _check_fit_settings(inset_px: float, max_pixels: int, huber_k: float, n_iterations: int) -> None:
    """One precise ``ValueError`` for a setting of :func:`fit_shading` out of its range."""
    if not (math.isfinite(inset_px) and inset_px >= 0):
        raise ValueError(f"inset_px: must be a finite number >= 0, got {inset_px!r}")
    if not (isinstance(max_pixels, (int, np.integer)) and max_pixels >= 50):
        raise ValueError(f"max_pixels: must be an integer >= 50, got {max_pixels!r}")
    if not (math.isfinite(huber_k) and huber_k > 0):
        raise ValueError(f"huber_k: must be a finite number > 0, got {huber_k!r}")
    if not (isinstance(n_iterations, (int, np.integer)) and n_iterations >= 1):
        raise ValueError(f"n_iterations: must be an integer >= 1, got {n_iterations!r}")


def fit_shading(
    camera: LineScanCamera,
    motion: BallMotion,
    data_dn: np.ndarray,
    lines: np.ndarray,
    t_lines_s: np.ndarray,
    left_px: np.ndarray,
    right_px: np.ndarray,
    *,
    inset_px: float = 1.5,
    max_pixels: int = 800,
    huber_k: float = 1.5,
    n_iterations: int = 4,
    usable: np.ndarray | None = None,
    usable_origin: tuple[int, int] = (0, 0),
) -> ShadingModel | None:
    """Fit the shading law to the pixels well inside the ball.

    Parameters
    ----------
    camera : LineScanCamera
    motion : BallMotion
        The ball's motion, roughly (the key-point guess, or a loose first fit).
    data_dn : ndarray (n_lines, W)
        The image, DN.
    lines : ndarray of int
        Image lines to use (those with both edges usable).
    t_lines_s : ndarray
        Centre time of each of ``lines``, seconds.
    left_px, right_px : ndarray
        Edges of each of ``lines`` (pixels); pixels more than ``inset_px``
        inside both are used.
    inset_px : float
        Distance from the edges, pixels.
    max_pixels : int
        At most this many pixels (an even subsample), for speed.
    huber_k : float
        Huber threshold in robust sigmas.
    n_iterations : int
        Reweighting rounds.
    usable : ndarray of bool (h, w), optional
        Pixels of a box that may be used (False: saturated, another ball's,
        ...); pixels outside the box are not used.
    usable_origin : (int, int)
        Image line and sensor pixel of ``usable[0, 0]``.

    Returns
    -------
    ShadingModel or None
        None when fewer than 50 interior pixels exist.

    Raises
    ------
    ValueError
        If a setting is out of its range (``inset_px >= 0``, ``max_pixels
        >= 50``, ``huber_k > 0``, ``n_iterations >= 1``; the message names it).
    """
    _check_fit_settings(inset_px, max_pixels, huber_k, n_iterations)
    width = data_dn.shape[1]
    # (np.clip's values, without its overhead)
    lo = np.minimum(np.maximum(np.ceil(np.asarray(left_px) + inset_px), 0), width - 1).astype(int)
    hi = np.minimum(np.maximum(np.floor(np.asarray(right_px) - inset_px), -1), width - 1).astype(int)
    counts = np.maximum(hi - lo + 1, 0)
    end = np.cumsum(counts)
    total = int(end[-1]) if end.size else 0
    if total < 50:
        return None
    # the pixels' indices in the lines' runs laid end to end, and only the
    # picked ones' lines and columns
    pick = _even_picks(total, max_pixels) if total > max_pixels else np.arange(total)
    row = np.searchsorted(end, pick, side="right")
    col = pick - (end - counts)[row] + lo[row]
    # (compiled: surface_normals at the pixels' centres and the usable box)
    m = motion
    hit, n, rays_ok = interior_normals(
        as_arg(t_lines_s[row]), as_arg(col, np.int64), as_arg(lines[row], np.int64),
        as_arg(np.zeros((0, 0), dtype=bool) if usable is None else usable, np.bool_), int(usable_origin[0]), int(usable_origin[1]),
        float(camera.focal_px), float(camera.principal_px), float(camera.k1), float(camera.k2), np.array(m.position_m, dtype=float),
        np.array(m.velocity_mps, dtype=float), np.array(m.acceleration_mps2, dtype=float), float(m.t_c_s), float(m.radius_m),
    )
    if not rays_ok:
        raise GeometryError("inverse distortion did not converge: coordinate outside the monotonic range of k1, k2")
    if not hit.all():
        row, col, n = row[hit], col[hit], n[hit]
    y = data_dn[lines[row], col].astype(float)
    if y.size < 50:
        return None
    # The rounds (compiled): the law is linear in (A, b) on the lit pixels,
    # shadowed ones see A only, and the lit / shadowed split makes the rounds
    # a fixed-point iteration, not a descent: on a flat ball a round that
    # calls half of it shadowed can run away to a strong light (seen: 152 DN
    # of light and a robust scale of 40 DN where the flat law leaves 5 DN;
    # its end levels then moved a ball's V.x by 21 sigma), so the best round
    # is kept when the last one's scale is _DIVERGED times worse.  A light
    # that lights hardly any of the pixels (behind the ball: seen on flat
    # 8-bit renders, 19-117 DN of light on a 138 DN contrast at the same
    # robust scale as no light) is not measured: the flat law, unless the
    # light lowers the robust scale by more than _FLAT_TOL.
    coef, scale = shading_fit(as_arg(y), as_arg(n), float(huber_k), int(n_iterations), float(_DIVERGED), float(_FLAT_TOL))
    return ShadingModel(float(coef[0]), (float(coef[1]), float(coef[2]), float(coef[3])), float(scale), int(y.size))


@dataclass(frozen=True, eq=False)
class LimbProfile:
    """The model's normalised profile across either edge of any line (see :func:`limb_profile`).

    Calling it with ``(lines, sides, offsets)`` -- image lines (R,), sides
    (R,) (+1 left, -1 right edge) and offsets (R, M) in pixels from the
    model's mean edge, positive inwards -- returns ``(value, coverage)``:
    the expected normalised value ``polarity (I - background) / contrast``
    of a point-like pixel there (the surface brightness times the fraction
    of the exposure and of the pixel's height in which the ball covers it)
    and that fraction.  NaN on lines where the model has no edge.  With
    ``average=False`` every line is sampled once, at its centre time through
    the pixel's centre (enough well inside the limb, where the ball covers
    the pixel throughout).

    Attributes
    ----------
    shading : ShadingModel
        The fitted law.
    camera : LineScanCamera
    motion : BallMotion
        The motion the normals and edges are computed at.
    t_lines_s : ndarray (n_lines,)
        Centre time of every image line, seconds.
    background_dn : ndarray (n_lines, W)
        The image's background, DN (not copied: not to be modified).
    polarity : int
        +1 for a ball brighter than the background, -1 for darker.
    contrast_dn : float
        The edges' normalisation, DN.
    spread_px, left_px, right_px : ndarray (n_lines,)
        The averaged silhouette's edge spread and mean edges per image line,
        pixels (NaN where the ball is absent).
    sharp_px : float
        Lines whose edge spread is below this are sampled once per position.
    n_time, n_height : int
        Samples over the exposure and across the pixel's height elsewhere.
    level_rel_sigma : float
        Relative 1-sigma of the law's prediction of a line's mean brightness
        over ``level_ref_px`` pixels (texture, seams, the law's own error;
        pixel noise removed), see :func:`ball_limb`.
    level_ref_px : float
        Length over which ``level_rel_sigma`` was measured, pixels; a line
        covered over ``c`` pixels gets ``level_rel_sigma * sqrt(level_ref_px
        / c)`` (:meth:`line_levels`): texture averages out over a line.
    level_n_time, level_n_height : int
        Samples over the exposure and across the pixel's height for the
        ends' mean brightness (:meth:`line_levels`).

    The camera's blur circle (``camera.defocus_px``, :mod:`ballscan.measure.defocus`)
    is in the profile: across the sensor in the averaged silhouette's chord
    samples, along it by averaging the profile's values and coverage over
    its marginal (:func:`ballscan.model.blur.semicircle_nodes`); the
    surface's brightness (:meth:`surface`) and the ends' levels
    (:meth:`line_levels`, whose integral the blur keeps) are not blurred.
    """

    shading: ShadingModel
    camera: LineScanCamera
    motion: BallMotion
    t_lines_s: np.ndarray
    background_dn: np.ndarray
    polarity: int
    contrast_dn: float
    spread_px: np.ndarray
    left_px: np.ndarray
    right_px: np.ndarray
    sharp_px: float = 0.1
    n_time: int = 3
    n_height: int = 2
    level_rel_sigma: float = 0.0
    level_ref_px: float = 1.0
    level_n_time: int = 3
    level_n_height: int = 2
    # the chord samples of the last rows pixel_coverage was asked for
    _samples: dict = field(default_factory=dict, init=False, repr=False, compare=False)
    # the profile without the blur (sharp())
    _sharp: dict = field(default_factory=dict, init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        if self.polarity not in (1, -1):
            raise ValueError(f"LimbProfile.polarity: must be +1 or -1, got {self.polarity!r}")
        for name in ("n_time", "n_height", "level_n_time", "level_n_height"):
            v = getattr(self, name)
            if not (isinstance(v, (int, np.integer)) and not isinstance(v, bool) and v >= 1):
                raise ValueError(f"LimbProfile.{name}: must be an integer >= 1, got {v!r}")
        # inf: every line sampled once per position
        if not self.sharp_px >= 0:
            raise ValueError(f"LimbProfile.sharp_px: must be a number >= 0 (inf allowed), got {self.sharp_px!r}")
        # NaN: the scatter was not measured (see ball_limb)
        if self.level_rel_sigma < 0 or self.level_rel_sigma == math.inf:
            raise ValueError(f"LimbProfile.level_rel_sigma: must be >= 0 and finite, or NaN, got {self.level_rel_sigma!r}")
        if not (math.isfinite(self.level_ref_px) and self.level_ref_px > 0):
            raise ValueError(f"LimbProfile.level_ref_px: must be a finite number > 0, got {self.level_ref_px!r}")

    @property
    def blur_px(self) -> float:
        """The camera's blur-circle diameter that the profile carries, pixels (0: in focus; :func:`ballscan.model.blur.blur_diameter`)."""
        return blur_diameter(self.camera)

    def sharp(self) -> "LimbProfile":
        """This profile without the blur, along the sensor and across it (the averaged silhouette of a camera in focus); made once."""
        if self.blur_px == 0:
            return self
        if "sharp" not in self._sharp:
            self._sharp["sharp"] = replace(self, camera=replace(self.camera, defocus_px=None))
        return self._sharp["sharp"]

    def line_levels(self, lines: np.ndarray, samples_per_px: int = 2) -> tuple[np.ndarray, np.ndarray]:
        """The model's mean brightness over the part of each line the ball covers.

        A line's summed normalised profile (its ``area``) is the covered
        length times this level; at the ball's ends the covered part is the
        cap, lit or shaded unlike the ball's middle, so the level divides the
        area into a covered length the silhouette model predicts.

        Parameters
        ----------
        lines : ndarray of int (R,)
            Image lines.
        samples_per_px : int
            Positions per pixel along the line (each averaged over the
            exposure and the pixel's height).

        Returns
        -------
        level : ndarray (R,)
            Normalised brightness ``polarity (I - background) / contrast``
            averaged over the ball's covered samples; NaN where the model
            does not see the ball.
        rel_sigma : ndarray (R,)
            Its relative 1-sigma (``level_rel_sigma`` scaled to the line's
            covered length, see the attributes; NaN with the level).
        """
        lines = np.asarray(lines, dtype=int)
        if lines.size == 0:
            return np.zeros(0), np.zeros(0)
        left, right, spread = self.left_px[lines], self.right_px[lines], self.spread_px[lines]
        m = max(int(samples_per_px), 1)
        # (compiled) each line's positions from pad outside its left edge over
        # span, the NaN spreads and edges taken as 0 as by np.nan_to_num
        pad, span, top = level_spans(as_arg(left), as_arg(right), as_arg(spread), m)
        n_pos = int(np.ceil(top)) if top == top else 1
        offsets = -pad[:, None] + (np.arange(max(n_pos, 1)) + 0.5)[None, :] / m
        inside = offsets <= (span - pad)[:, None]
        # the sums over the inside positions (compiled: the points' model and its sums in one pass)
        val_sum, covered, rays_ok = line_level_sums(
            offsets, inside, as_arg(left), as_arg(self.t_lines_s[lines]), as_arg(~(spread >= self.sharp_px), np.bool_), as_arg(lines, np.int64),
            *self._model(self.level_n_time, self.level_n_height),
        )
        if not rays_ok:
            raise GeometryError("inverse distortion did not converge: coordinate outside the monotonic range of k1, k2")
        with np.errstate(invalid="ignore", divide="ignore"):
            level = val_sum / covered
            level = np.where((covered > 0) & np.isfinite(left) & np.isfinite(right), level, np.nan)
            rel = self.level_rel_sigma * np.sqrt(self.level_ref_px / np.maximum(covered / m, 1.0))
        return level, np.where(np.isfinite(level), rel, np.nan)

    def pixel_coverage(self, lines: np.ndarray, sides: np.ndarray, offsets: np.ndarray, n_nodes: int = 4) -> np.ndarray:
        """Covered fraction of whole pixels across either edge (``pixel_coverage`` of a ``limb`` of :func:`ballscan.measure.edges.measure_edges`).

        Unlike :meth:`__call__`, which samples points, this is each whole
        pixel's overlap with the averaged silhouette's chord samples
        (:func:`ballscan.model.pixels.pixel_coverage`), placed so that the model's mean
        edge sits at offset 0.  Near a ball's ends a spread edge's samples
        have long tails: a pixel 2-3 px inside the mean edge is still
        uncovered for a few per cent of them, which a few point samples miss
        (a noise-free render's level runs of the wide windows would read
        about 1 % darker than the point model, and their edges a few
        hundredths of a pixel outward).  ``n_nodes`` Gauss-Legendre nodes per
        piece over the exposure and the pixel's height: a quadrature of a
        function with kinks, per pixel within about 0.01 (0.02 on the fastest
        balls) of a finely supersampled render where the edge spreads
        0.2-1 px; more nodes bring it closer.

        Parameters
        ----------
        lines : ndarray of int (R,)
            Image lines.
        sides : ndarray (R,)
            +1 for the left edge, -1 for the right one.
        offsets : ndarray (R, K)
            Pixel centres' offsets from the edge, pixels, positive inwards;
            each pixel spans its offset +- 1/2.
        n_nodes : int

        Returns
        -------
        ndarray (R, K)
            Fraction of the exposure and of the pixel's area the ball
            covers; NaN on lines where the model has no edge.
        """
        lines = np.asarray(lines, dtype=int)
        sg = np.asarray(sides, dtype=float)
        off = np.asarray(offsets, dtype=float)
        if lines.size == 0:
            return np.zeros(off.shape)
        lo, hi, wgt = self._chords(lines, sg, n_nodes)
        cov = pixel_coverage(lo[None], hi[None], wgt[None], off)[0]
        bad = ~np.isfinite(np.where(sg > 0, self.left_px[lines], self.right_px[lines]))[:, None]
        return np.where(bad, np.nan, cov)

    def _chords(self, lines: np.ndarray, sg: np.ndarray, n_nodes: int, blurred: bool = True) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """The averaged silhouette's chord samples of each row as intervals of offsets inwards from its edge, pixels, and their weights (R, 3, n).

        With a blur (``blur_px``: the averaged silhouette's 3 B pieces, B
        offsets across the sensor) and ``blurred`` each sample is repeated
        at the blur's 12 nodes along the sensor, (R, 3 B, 12 n).  Computed once per line (a line's two edges and windows share them)
        and kept for the next call on the same rows.
        """
        blurred = blurred and self.blur_px > 0
        key = (int(n_nodes), blurred, lines.tobytes(), sg.tobytes())
        if key not in self._samples:
            uniq, inv = _unique_lines(lines)
            me = averaged_model(
                self.camera, self.motion.to_params()[None], self.motion.radius_m, self.t_lines_s[uniq],
                self.motion.acceleration_mps2, n_nodes=n_nodes, return_samples=True,
            )
            shape = me.samples[0].shape[1:]  # (U, 3, n)
            # (compiled: each row's line's samples, from its edge)
            lo, hi, wgt = chord_rows(
                *(as_arg(a[0].reshape(shape[0], shape[1] * shape[2])) for a in me.samples), as_arg(me.left_px[0]), as_arg(me.right_px[0]),
                as_arg(inv, np.int64), as_arg(sg),
            )
            lo, hi, wgt = (a.reshape((lines.size,) + shape[1:]) for a in (lo, hi, wgt))
            if blurred:
                # the blur's marginal along the sensor: each chord shifted by its nodes
                # (both ends alike, so either side's inward offsets), weights multiplied
                shift, w = semicircle_nodes(self.blur_px, ALONG_NODES)
                lo, hi = ((a[..., None] + shift).reshape(lines.size, a.shape[1], -1) for a in (lo, hi))
                wgt = (wgt[..., None] * w).reshape(lines.size, wgt.shape[1], -1)
            self._samples.clear()
            self._samples[key] = (lo, hi, wgt)
        return self._samples[key]

    def rows(self, lines: np.ndarray, sides: np.ndarray, n_nodes: int = 4) -> tuple:
        """The model of edges ``(lines, sides)`` as the model arguments of :func:`ballscan.measure._shading_kernels.limb_levels`.

        Each row's chord samples (:meth:`pixel_coverage`'s, ``n_nodes``
        nodes) flattened to (R, 3 n), its line time, mean edge (NaN where
        the model has none), whether its edge is sharp (one point sample,
        see the attributes), its line, the background, the samples over the
        exposure and the pixel's height, the camera's focal length,
        principal point and distortion and the shading law (the arguments
        of :func:`ballscan.measure._shading_kernels.limb_values` from ``pos`` on),
        and the blur's shifts and weights along the sensor (the kernel moves
        the profile itself: its surface's brightness moves with it).
        """
        lines = np.asarray(lines, dtype=int)
        sg = np.asarray(sides, dtype=float)
        lo, hi, wgt = (as_arg(a.reshape(lines.size, -1)) for a in self._chords(lines, sg, n_nodes, blurred=False))
        shift, w = semicircle_nodes(self.blur_px, ALONG_NODES)
        return (
            lo, hi, wgt, as_arg(self.t_lines_s[lines]), as_arg(np.where(sg > 0, self.left_px[lines], self.right_px[lines])),
            as_arg(~(self.spread_px[lines] >= self.sharp_px), np.bool_), as_arg(lines, np.int64), *self._model(), as_arg(shift), as_arg(w),
        )

    def _model(self, n_time: int | None = None, n_height: int | None = None) -> tuple:
        """The background, the samples, the camera and the shading law as the last arguments of the compiled levels (:func:`ballscan.measure._shading_kernels.limb_levels`).

        ``n_time`` and ``n_height`` (default the profile's) set the samples
        over the exposure and the pixel's height.
        """
        cam = self.camera
        return (
            as_arg(self.background_dn), *self._samples_tk_hk(n_time, n_height), float(cam.focal_px), float(cam.principal_px), float(cam.k1), float(cam.k2),
            *self._law(),
        )

    def _samples_tk_hk(self, n_time: int | None = None, n_height: int | None = None) -> tuple[np.ndarray, np.ndarray]:
        """The instants over the exposure (s, from the line's centre time) and heights across the pixel (pixels) an unsharp edge is sampled at."""
        n_t = self.n_time if n_time is None else int(n_time)
        n_h = self.n_height if n_height is None else int(n_height)
        # (a few values: numpy's float64 arithmetic on Python floats, without its per-operation overhead)
        exposure = float(self.camera.exposure)
        tk = np.array([((k + 0.5) / n_t - 0.5) * exposure for k in range(n_t)], dtype=float)
        hk = np.array([(k + 0.5) / n_h - 0.5 for k in range(n_h)], dtype=float)
        return tk, hk

    def _law(self) -> tuple:
        """The motion and the shading law as the last arguments of :func:`ballscan.measure._shading_kernels.limb_values`."""
        m = self.motion
        return (
            np.array(m.position_m, dtype=float), np.array(m.velocity_mps, dtype=float), np.array(m.acceleration_mps2, dtype=float),
            float(m.t_c_s), float(m.radius_m), np.array(self.shading.light_dn, dtype=float), float(self.shading.ambient_dn),
            float(self.polarity * self.contrast_dn),
        )

    def surface(self, lines: np.ndarray, sides: np.ndarray, offsets: np.ndarray) -> np.ndarray:
        """The shading law's normalised brightness of the surface at ``offsets`` (at least a quarter pixel inside the edge).

        Arguments as for :meth:`__call__`; one sample per position at the
        line's centre time; NaN where the model does not see the ball there.
        """
        val, hit = self.sharp()(lines, sides, np.maximum(np.asarray(offsets, dtype=float), 0.25), average=False)
        return np.where(hit > 0, val, np.nan)

    def __call__(self, lines: np.ndarray, sides: np.ndarray, offsets: np.ndarray, average: bool = True) -> tuple[np.ndarray, np.ndarray]:
        if self.blur_px > 0:
            # the blur's marginal along the sensor: the sharp profile averaged over its nodes
            off = np.asarray(offsets, dtype=float)
            shift, w = semicircle_nodes(self.blur_px, ALONG_NODES)
            val, cov = self.sharp()(lines, sides, (off[..., None] + shift).reshape(off.shape[0], -1), average)
            bad = np.isnan(val).all(axis=1)[:, None]  # the rows where the model has no edge
            val, cov = (np.nan_to_num(a).reshape(off.shape + (w.size,)) @ w for a in (val, cov))
            return np.where(bad, np.nan, val), np.where(bad, np.nan, cov)
        lines = np.asarray(lines, dtype=int)
        sides = np.asarray(sides)
        width = self.background_dn.shape[1]
        edge = np.where(sides > 0, self.left_px[lines], self.right_px[lines])
        u = edge[:, None] + sides[:, None] * np.asarray(offsets, dtype=float)
        # the background's column under each position (where u is not finite
        # no ray meets the ball and the value is 0 whatever the background):
        # clamped before rounding, the same columns as clipping after it
        cols = np.rint(np.fmin(np.fmax(u, 0.0), width - 1.0)).astype(int)
        bg = self.background_dn[lines[:, None], cols]
        # a sharp edge hardly moves during the exposure or across the
        # pixel's height: one sample at the line's centre time will do
        sharp = ~(self.spread_px[lines] >= self.sharp_px) | (not average)
        # contiguous and writeable arrays: the kernel's one compiled signature
        val_out, cov_out = limb_values(
            as_arg(self.t_lines_s[lines]), as_arg(self.camera.backproject(u)), as_arg(bg), as_arg(sharp, np.bool_),
            *self._samples_tk_hk(), float(self.camera.focal_px), *self._law(),
        )
        bad = ~np.isfinite(edge)[:, None]
        return np.where(bad, np.nan, val_out), np.where(bad, np.nan, cov_out)


def _even_picks(n: int, m: int) -> np.ndarray:
    """``np.linspace(0, n - 1, m).astype(int)``: the same arithmetic (``k * step``, the last exactly ``n - 1``) without its overhead."""
    if m < 2:
        return np.linspace(0, n - 1, m).astype(int)
    pick = (np.arange(m) * ((n - 1) / (m - 1))).astype(int)
    pick[-1] = n - 1
    return pick


def _nan_to_num(a: np.ndarray) -> np.ndarray:
    """``np.nan_to_num`` of a float64 array (a new array), at a fraction of its cost where no value is infinite."""
    out = np.where(np.isnan(a), 0.0, a)
    return np.nan_to_num(a) if np.isinf(out).any() else out


def _unique_lines(lines: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``np.unique(lines, return_inverse=True)`` of image lines (1-D integers within an image's height), without its sort.

    The lines of a ball's rows span some hundred consecutive values: a table
    of them (compiled, :func:`ballscan.measure._shading_kernels.unique_lines`) gives the same
    sorted values and inverse at a fraction of the cost.
    """
    if lines.size == 0:
        return np.unique(lines, return_inverse=True)
    return unique_lines(as_arg(lines, np.int64))


def limb_profile(
    shading: ShadingModel,
    camera: LineScanCamera,
    motion: BallMotion,
    t_lines_s: np.ndarray,
    background_dn: np.ndarray,
    polarity: int,
    contrast_dn: float,
    spread_px: np.ndarray,
    left_px: np.ndarray,
    right_px: np.ndarray,
    *,
    sharp_px: float = 0.1,
    n_time: int = 3,
    n_height: int = 2,
    level_rel_sigma: float = 0.0,
    level_ref_px: float = 1.0,
    level_n_time: int = 3,
    level_n_height: int = 2,
) -> LimbProfile:
    """The model's normalised profile across either edge of any line.

    Parameters
    ----------
    shading : ShadingModel
    camera : LineScanCamera
    motion : BallMotion
    t_lines_s : ndarray (n_lines,)
        Centre time of every image line, seconds.
    background_dn : ndarray (n_lines, W)
        Background of the image, DN.
    polarity : int
        +1 for a ball brighter than the background, -1 for darker.
    contrast_dn : float
        The normalisation of :func:`ballscan.measure.edges.measure_edges`, DN.
    spread_px, left_px, right_px : ndarray (n_lines,)
        The averaged silhouette's edge spread and mean edges of every line
        (:func:`ballscan.model.averaged.averaged_model` at ``motion``), pixels; NaN
        where the ball is absent.
    sharp_px : float
        Lines whose edges spread less than this over the exposure and the
        pixel's height are evaluated at the line's centre time through the
        pixel's centre; the others average ``n_time x n_height`` samples.
    n_time, n_height : int
        Samples over the exposure and across the pixel's height.
    level_rel_sigma, level_ref_px : float
        Relative 1-sigma of the law's mean brightness of a line and the
        length it was measured over, pixels (see :class:`LimbProfile`).
    level_n_time, level_n_height : int
        Samples over the exposure and the pixel's height for the ends' mean
        brightness (:meth:`LimbProfile.line_levels`).

    Returns
    -------
    LimbProfile
    """
    return LimbProfile(
        shading, camera, motion, np.asarray(t_lines_s, dtype=float), background_dn, int(polarity), float(contrast_dn),
        np.asarray(spread_px, dtype=float), np.asarray(left_px, dtype=float), np.asarray(right_px, dtype=float),
        float(sharp_px), int(n_time), int(n_height), float(level_rel_sigma), float(level_ref_px), int(level_n_time), int(level_n_height),
    )


def ball_limb(
    camera: LineScanCamera,
    motion: BallMotion,
    data_dn: np.ndarray,
    edges: EdgeMeasurements,
    t_lines_s: np.ndarray,
    background_dn: np.ndarray,
    *,
    level_samples: tuple[int, int] = (3, 2),
) -> LimbProfile | None:
    """Fit the ball's shading and build its edge profile model in one step.

    Parameters
    ----------
    camera, motion, data_dn
        As for :func:`fit_shading`.
    edges : EdgeMeasurements
        The first (model-free) edges of the ball.
    t_lines_s : ndarray (n_lines,)
        Centre time of every image line, seconds.
    background_dn : ndarray (n_lines, W)
        Background of the image, DN.
    level_samples : (int, int)
        Samples over the exposure and the pixel's height for the ends' mean
        brightness (``level_n_time, level_n_height`` of :func:`limb_profile`).

    Returns
    -------
    LimbProfile or None
        None when the ball shows too few interior pixels for the fit.
    """
    theta = motion.to_params()[None]
    me = averaged_model(camera, theta, motion.radius_m, edges.t_s, motion.acceleration_mps2)
    both = edges.left_ok & edges.right_ok & (me.presence[0] > 0)
    # interior: inside both the model's and the measured edges (the model is
    # at a rough motion), and not saturated or another ball's (NaN in the
    # edges' profile)
    inner = (np.fmax(me.left_px[0], edges.left_px), np.fmin(me.right_px[0], edges.right_px))
    if "cut_sensor_end" in edges.flags:
        both, inner = _cut_interior(edges, me.left_px[0], me.right_px[0], me.presence[0], data_dn.shape[1])
    left, right = inner[0][both], inner[1][both]
    # the edges' lines are consecutive: their profile is a box of the image
    usable = None if edges.profile is None else np.isfinite(edges.profile)
    shading = fit_shading(
        camera, motion, data_dn, edges.lines[both], edges.t_s[both], left, right,
        # the blur circle's rim of blurred pixels is not the surface's shading
        inset_px=1.5 + 0.5 * blur_diameter(camera),
        usable=usable, usable_origin=(int(edges.lines[0]), int(edges.profile_col0)),
    )
    if shading is None:
        return None
    # the spread and edges of every image line (rows of one array)
    per_line = np.full((3, np.asarray(t_lines_s).size), np.nan)
    seen = np.array((me.spread_px[0], me.left_px[0], me.right_px[0]))
    seen[:, ~(me.presence[0] > 0)] = np.nan
    per_line[:, edges.lines] = seen
    limb = limb_profile(
        shading, camera, motion, t_lines_s, background_dn, edges.polarity, edges.contrast_dn, *per_line,
        level_n_time=int(level_samples[0]), level_n_height=int(level_samples[1]),
    )
    # how well the law predicts a line's mean brightness, measured on the
    # plateau lines and scaled to each end line's length, is the sigma of the
    # end lines' levels
    # lines seen during the whole exposure, one line away from any that is
    # not (the guess's presence may be off by a line; a partial line's mean
    # is far lower)
    full = both & (me.presence[0] > 0.999)
    for _ in range(_level_margin(int(full.sum()))):
        kept = np.zeros_like(full)
        kept[1:-1] = full[:-2] & full[1:-1] & full[2:]
        full = kept
    scatter, length = _line_level_scatter(limb, edges, full, me.spread_px[0], *inner)
    return replace(limb, level_rel_sigma=scatter, level_ref_px=length)


def _cut_interior(
    edges: EdgeMeasurements, left_px: np.ndarray, right_px: np.ndarray, presence: np.ndarray, width_px: int
) -> tuple[np.ndarray, tuple[np.ndarray, np.ndarray]]:
    """The lines and interior of a ball cut by the sensor's end: one usable edge a line is enough.

    On each line the interior lies inside the model's edges, inside each
    usable measured edge, and on the sensor (pixels 0 .. W-1, the cut side
    ending at the sensor's last pixel).  Returns the lines to use and the
    interior's (left, right) on every line, pixels.
    """
    left = np.fmax(left_px, np.where(edges.left_ok, edges.left_px, np.nan))
    right = np.fmin(right_px, np.where(edges.right_ok, edges.right_px, np.nan))
    left = np.maximum(left, -0.5)
    right = np.minimum(right, width_px - 0.5)
    lines = (edges.left_ok | edges.right_ok) & (presence > 0) & (right > left)
    return lines, (left, right)


def _level_margin(n_full: int) -> int:
    """Lines left out at each end of the plateau lines for the level scatter.

    The rough motion's presence can be off by a line, and on a long ball by
    more (the key-point guess's duration is good to about a percent): on a
    fast ball it calls lines at each end full that the ball entered during
    the exposure, whose means, several percent low, would make a flat
    ball's scatter large enough to refuse it as not uniform.  One line up
    to 250 lines, 0.6 % of them beyond.
    """
    return max(1, int(round(0.006 * n_full)))


def _line_level_scatter(
    limb: LimbProfile, edges: EdgeMeasurements, lines_ok: np.ndarray, spread_px: np.ndarray, left_px: np.ndarray, right_px: np.ndarray, max_lines: int = 40
) -> tuple[float, float]:
    """Relative scatter of the lines' measured mean brightness about the law's, pixel noise removed.

    The end lines' areas are divided by the law's mean brightness of their
    covered part (:meth:`LimbProfile.line_levels`); how well the law predicts
    a line's mean is measured here on the lines with a plateau (their
    pixels at least 1.5 px plus the edge spread inside both edges): a seam
    crossing a line changes its mean by a good part of its contrast, which a
    robust pixel scale would not see.  At most ``max_lines`` lines, evenly
    spread; ``lines_ok`` must leave out the lines on which the ball is
    present during only part of the exposure (their mean is lower);
    returns the scatter and the mean number of pixels per line it was
    measured over (``(nan, 1)`` when fewer than 3 lines qualify: not
    measured is not uniform);
    ``left_px``, ``right_px`` are the edges inside both the model's and the
    measured ones (a narrow-window edge of a spread end is off by a pixel).
    """
    if edges.profile is None or edges.profile_sigma is None:
        return math.nan, 1.0
    idx = np.flatnonzero(lines_ok)
    if idx.size > max_lines:
        idx = idx[_even_picks(idx.size, max_lines)]
    inset = 1.5 + _nan_to_num(spread_px[idx])
    c0 = edges.profile_col0
    lo = np.ceil(left_px[idx] + inset).astype(int) - c0
    hi = np.floor(right_px[idx] - inset).astype(int) - c0
    # (integers: np.clip's values, without its overhead)
    lo, hi = np.minimum(np.maximum(lo, 0), edges.profile.shape[1]), np.minimum(np.maximum(hi, -1), edges.profile.shape[1] - 1)
    count = hi - lo + 1
    keep = count >= 3
    if keep.sum() < 3:
        return math.nan, 1.0
    idx, lo, count = idx[keep], lo[keep], count[keep]
    lines_img = edges.lines[idx]
    # (compiled) the lines' means where the model's surface is seen too (the
    # model sits at a rough motion: a pixel inside the measured ball may lie
    # outside its silhouette), their scatter and its noise
    scatter, length, rays_ok = level_scatter(
        as_arg(lines_img, np.int64), as_arg(lo, np.int64), as_arg(count, np.int64), as_arg(idx, np.int64), as_arg(edges.profile),
        as_arg(edges.profile_sigma), int(c0), as_arg(limb.left_px[lines_img]), as_arg(limb.t_lines_s[lines_img]), *limb._model(),
    )
    if not rays_ok:
        raise GeometryError("inverse distortion did not converge: coordinate outside the monotonic range of k1, k2")
    return float(scatter), float(length)


def shade_profile(limb: LimbProfile, edges: EdgeMeasurements, min_spread_px: float = 0.2) -> np.ndarray | None:
    """The shading model's surface brightness under every pixel of the ball's ends.

    For :attr:`ballscan.measure.edges.EdgeMeasurements.profile_shade` (the fit's
    pixel model multiplies each pixel's coverage by it): on the lines with
    signal whose model edge spread is at least ``min_spread_px`` or that lack
    an edge pair, the normalised brightness of the surface seen through each
    pixel of the edges' profile box (outside the silhouette, of the surface
    nearest to it, a quarter pixel inside); 1 on the other lines; NaN on
    lines where the model does not see the ball (the pixel model then uses 1).

    Parameters
    ----------
    limb : LimbProfile
    edges : EdgeMeasurements
        With a profile (made by :func:`ballscan.measure.edges.measure_edges`).
    min_spread_px : float
        Pixels, ``>= 0``.

    Returns
    -------
    ndarray (n_lines, n_cols) or None
        None when ``edges`` carry no profile.

    Raises
    ------
    ValueError
        If ``min_spread_px`` is negative or NaN.
    """
    if not min_spread_px >= 0:
        raise ValueError(f"min_spread_px: must be a number >= 0, got {min_spread_px!r}")
    if edges.profile is None:
        return None
    lines = edges.lines
    spread = limb.spread_px[lines]
    n_cols = edges.profile.shape[1]
    out = np.ones((lines.size, n_cols))
    pair = edges.left_ok & edges.right_ok
    want = np.flatnonzero(edges.signal & np.isfinite(spread) & ((spread >= min_spread_px) | ~pair))
    if want.size == 0:
        return out
    left, right = limb.left_px[lines[want]], limb.right_px[lines[want]]
    u = edges.profile_col0 + np.arange(n_cols, dtype=float)[None, :]
    chord = np.maximum(right - left, 0.5)
    off = np.clip(u - left[:, None], 0.25, np.maximum(chord - 0.25, 0.25)[:, None])
    out[want] = limb.surface(lines[want], np.ones(want.size), off)
    return out
