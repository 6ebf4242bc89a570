"""Sub-pixel edge measurement on every scan line of a detected ball.

For each line the profile is normalised, ``p_j = polarity (I_j - bg_j) / |contrast|``
(about 0 outside the ball and about 1 inside it), and each of the two edges is
located by a *local area* estimate:

* a rough position ``k`` is the first (left) or last (right) pixel whose
  ``p`` reaches a quarter of the line's peak;
* the inner level ``L`` is taken *locally*, as the mean of ``p`` over the
  ``n_level`` pixels just inside the edge window (the limb is shaded and the
  felt/seam texture varies, so the ball's global contrast would bias the
  edge by tenths of a pixel);
* the edge is the uncovered length of a window ``[a, b]`` of pixels
  straddling the transition, ``e_left = a - 1/2 + sum_j (1 - p_j / L)`` and
  ``e_right = b + 1/2 - sum_j (1 - p_j / L)``.

For a box pixel (pixel ``j`` spans ``[j - 1/2, j + 1/2]``) the summed partial
coverage of the window is exact whatever the sub-pixel position, so the
estimate has no "pixel-locking" bias, and it recovers the *mean* edge over the
pixel's height and the exposure, which is exactly what
:func:`ballscan.model.silhouette.silhouette` (``model="averaged"``) predicts.  Its
standard deviation is the pixel noise propagated linearly through the
estimator (window pixels with weight ``1/L``, level pixels with weight
``S/L^2/n_level``, ``S`` the window's sum).

On the first and last lines of a ball the segment is short and faint (the
ball is present during part of the exposure / part of the pixel's height):
there the edges are marked unusable and the line's summed coverage
``area_px = sum_j p_j`` (pixels) and its centroid are what the fit uses; they
are provided on every line.

A limb of the other sign (a bright ball's side in shadow darker than the
backdrop, a football's black panel) is found beyond the rough edge
(:func:`ballscan.measure._edge_kernels.other_sign_edges`) and its edge
measured on ``-p``, so that the same estimator and rules apply; such a
line's area mixes both signs and is kept out of the fit.

Edges are never dropped silently: an edge whose window reaches the sensor's
first or last pixel, contains a saturated pixel, meets another ball's region
or gives an estimate outside its window has ``left_ok`` / ``right_ok`` False.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from typing import Any, Callable, Sequence

import numpy as np

from ..compiled import as_arg
from ._edge_kernels import (
    edge_windows, finished_edges, finite_rows, inner_differences, level_gradients, limb_pixels, line_coverage,
    other_sign_edges, rough_edges, running_medians, shaded_sides, shot_noise, walk_edges, window_edges,
)
from ._shading_kernels import limb_levels
from ..errors import GeometryError
from .robust import median, weighted_median

__all__ = ["EdgeMeasurements", "EdgeSettings", "measure_edges", "with_limb", "without_edges"]


@dataclass(frozen=True)
class EdgeSettings:
    """Tuning of the local area edge estimator (pixels).

    Attributes
    ----------
    n_out : int
        Window pixels outside the rough edge pixel (besides the one next to
        it); they absorb edges spread over the exposure.
    n_in : int
        Window pixels inside the rough edge pixel.
    n_level : int
        Pixels just inside the window averaged for the local inner level.
    find_fraction : float
        Fraction of the line's peak that locates the rough edge pixel.
    margin_lines : int
        Lines measured before and after the detected region (their area,
        about 0, tells the fit where the ball is *not*).
    pad_px : int
        Columns added on both sides of the region's box.
    min_snr : float
        A line's peak must exceed this many noise sigmas to carry edges.
    n_out_wide, n_in_wide : int
        ``n_out`` and ``n_in`` of the wide window (spread edges).
    level_slope : float
        Extrapolation of the inner level towards the limb.  Limb shading
        makes the ball darker at its edge than one or two pixels inside,
        which biases the edge inwards; the level is extrapolated linearly
        from the gradient across the level run to the covered part of the
        edge pixel, ``L = L_run (1 - level_slope * d * g / L_run)``, ``g`` the
        gradient per pixel (inwards) and ``d`` the distance from the run's
        centre to the edge pixel's covered part (``n_in + 0.75 + (n_level -
        1) / 2`` pixels).  The relative correction is median-filtered over
        lines (``slope_degree``; shading is smooth from line to line, felt
        texture and noise are not).  0 uses the level run as it is.
    slope_lines : int
        Lines of the running median of the level gradient (fallback of the
        polynomial smoothing for short balls).
    slope_degree : int
        Degree of a robust polynomial (in the line index) that smooths the
        relative level gradient along each side instead of the running
        median; -1 (default) keeps the running median (a low-order polynomial
        cannot follow the blur at the ball's ends and biases the middle).
    slope_threshold : float
        The correction is applied on a side only when the smoothed relative
        gradient exceeds this many of its own sigmas on average over the
        side's lines.
    ball_noise : bool
        Estimate the ball's own pixel noise (shot noise grows with the
        signal) from second differences inside the segments and use
        ``sigma^2 = sigma_bg^2 + (sigma_ball^2 - sigma_bg^2) p / p_ball`` per
        pixel instead of the background's noise alone.
    max_walk_px : int
        Pixels the rough edge may move outwards from the peak-fraction
        crossing towards a darker (shaded) limb.  The walk ends where the
        profile stops holding ``find_fraction`` of its inner neighbour or
        falls to the noise floor, so the default bounds it only by the box:
        on a ball lit from the side with little ambient light the shaded
        side, at the ambient level, is a plateau below a quarter of a
        highlight's peak that can span a third of the diameter, and a
        window left at the terminator reads that side's limb pixels inside
        the ball by as much (the depth velocity then follows the
        terminator's path across the passage).
    walk_snr : float
        The walk's floor: the next pixel must exceed this many noise sigmas.
        Below ``min_snr``: a dim limb (a shaded side at the ambient level,
        blurred by defocus) fades into the noise pixel by pixel, and a walk
        that stops short leaves the window a pixel or two inside the limb;
        one that steps onto the background on a noise spike only widens the
        window by a pixel of background, which adds its noise but no bias.
    limb_samples : int
        Point samples per pixel of the profile model (``limb`` of
        :func:`measure_edges`) for the surface's mean brightness on the
        partly covered pixels of a window.
    limb_texture_tol : float
        With ``limb``, an edge keeps its model-free value when the relative
        change of the level from the level run to the run inside it differs
        from the model's by more than 3 sigma plus this (texture, not
        shading, near the edge).  Not 0: the model's run levels carry its
        own small errors (tenths of a percent on a spread edge next to a
        ball's end, where the run's last pixel is not quite covered), and on
        noise-free images a zero tolerance would keep the model-free edges
        there, a few hundredths of a pixel outward.
    limb_narrow_max_px, limb_wide_px : float, (float, float)
        With ``limb``, the narrow-window edges are corrected on lines whose
        model edge spread (``limb.spread_px``) is below ``limb_narrow_max_px``
        and the wide-window edges where it lies within ``limb_wide_px``: the
        lines where :func:`ballscan.solve.fit.fit_motion` uses each (the model's
        evaluation is the costly part); the others keep the model-free value.
    limb_area_min_spread_px : float
        With a ``limb`` that has ``line_levels``, the lines with signal whose
        model edge spread is at least this, or that lack a usable edge pair,
        get the model's brightness of their covered part
        (:attr:`EdgeMeasurements.area_level`): the lines whose area the fit
        uses (the ball's ends).
    other_sign_depth : float
        On a region of both signs (``region.both_signs``), the least depth,
        as a fraction of the ball's contrast, that a line's part of the
        other sign must reach (besides ``min_snr`` noise sigmas) for its
        edges to move onto it (a limb in shadow darker than the backdrop,
        :func:`ballscan.measure._edge_kernels.other_sign_edges`).  A ball of
        one sign never looks: a camera's sharpening halo is a thin ring of
        the other sign around every edge, under a tenth of the region.
    other_sign_run_px : int
        Pixels in a row, each at ``walk_snr`` noise sigmas, of the run of the
        other sign that an edge moves onto.
    """

    n_out: int = 1
    n_in: int = 0
    n_level: int = 2
    find_fraction: float = 0.25
    margin_lines: int = 2
    pad_px: int = 5
    min_snr: float = 6.0
    n_out_wide: int = 3
    n_in_wide: int = 1
    level_slope: float = 1.0
    max_walk_px: int = 4096
    walk_snr: float = 3.0
    slope_lines: int = 9
    slope_degree: int = -1
    slope_threshold: float = 2.0
    ball_noise: bool = True
    limb_samples: int = 3
    limb_texture_tol: float = 0.002
    limb_narrow_max_px: float = 0.45
    limb_wide_px: tuple[float, float] = (0.2, 1.0)
    limb_area_min_spread_px: float = 0.8
    other_sign_depth: float = 0.03
    other_sign_run_px: int = 2

    def __post_init__(self) -> None:
        for name, lo in (
            ("n_out", 0), ("n_in", 0), ("n_level", 1), ("margin_lines", 0), ("pad_px", 0), ("n_out_wide", 0),
            ("n_in_wide", 0), ("max_walk_px", 0), ("slope_lines", 1), ("slope_degree", -1), ("limb_samples", 1),
            ("other_sign_run_px", 2),
        ):
            v = getattr(self, name)
            if not (isinstance(v, (int, np.integer)) and not isinstance(v, bool) and v >= lo):
                raise ValueError(f"EdgeSettings.{name}: must be an integer >= {lo}, got {v!r}")
        for name in ("min_snr", "walk_snr", "slope_threshold", "limb_texture_tol", "limb_narrow_max_px", "limb_area_min_spread_px", "other_sign_depth"):
            v = getattr(self, name)
            if not (_is_number(v) and v >= 0):
                raise ValueError(f"EdgeSettings.{name}: must be a finite number >= 0, got {v!r}")
        if not (_is_number(self.find_fraction) and 0 < self.find_fraction < 1):
            raise ValueError(f"EdgeSettings.find_fraction: must lie in (0, 1), got {self.find_fraction!r}")
        if not _is_number(self.level_slope):
            raise ValueError(f"EdgeSettings.level_slope: must be a finite number, got {self.level_slope!r}")
        if not isinstance(self.ball_noise, (bool, np.bool_)):
            raise ValueError(f"EdgeSettings.ball_noise: must be a bool, got {self.ball_noise!r}")
        w = self.limb_wide_px
        if not (isinstance(w, tuple) and len(w) == 2 and all(_is_number(v) for v in w) and 0 <= w[0] <= w[1]):
            raise ValueError(f"EdgeSettings.limb_wide_px: must be a (low, high) pair of numbers, 0 <= low <= high, got {w!r}")


def _is_number(v: Any) -> bool:
    """A finite real number (not a bool)."""
    return isinstance(v, (int, float, np.integer, np.floating)) and not isinstance(v, bool) and math.isfinite(v)


@dataclass(frozen=True)
class EdgeMeasurements:
    """Per-line edge and area measurements of one ball.

    All arrays have one entry per measured line (the detected region plus
    ``margin_lines`` lines on each side, clipped to the image).

    Attributes
    ----------
    lines : ndarray of int
        Image line (row) indices.
    t_s : ndarray
        Centre time of each line, seconds.
    left_px, right_px : ndarray
        Mean edge positions over the pixel's height and the exposure, pixels
        (``u = j`` at the centre of pixel ``j``); NaN where not measured.
    left_sigma_px, right_sigma_px : ndarray
        1-sigma of the edges from the pixel noise, pixels.
    left_ok, right_ok : ndarray of bool
        Whether each edge is usable (see the module docstring).
    area_px : ndarray
        Summed normalised profile of the line (the ball's expected summed
        pixel coverage times its relative brightness), pixels.
    area_sigma_px : ndarray
        1-sigma of ``area_px`` from the pixel noise, pixels.
    centroid_px : ndarray
        ``sum(j p_j) / sum(p_j)`` over the summed columns, pixels; NaN where
        the area is not significant.
    level : ndarray
        Local inner level (mean of left and right levels, normalised units),
        NaN where no edge was measured.
    peak : ndarray
        Peak of the normalised profile on each line.
    end_line : ndarray of bool
        Lines with signal but no usable edge pair (short, faint segments at
        the ball's ends): the fit uses their area.
    polarity : int
        +1 for a ball brighter than the background, -1 for darker.
    contrast_dn : float
        ``|ball - background|`` used for the normalisation, DN.
    flags : tuple of str
        geometry.md flag words that apply (``cut_sensor_end``,
        ``saturated``, ``overlap``, ``both_signs``: an edge on a limb of the
        other sign).
    left_texture_px, right_texture_px : ndarray or None
        Texture/shading indicator of each edge, pixels: the window's covered
        length ``S / L`` times the relative change of the inner level between
        the two runs of ``n_level`` pixels inside the level run (less its
        noise; pixels the edge estimate does not use, so that the weight's
        noise is independent of the edge's).
        A uniform limb gives about 0; a seam or a steep shading gradient next
        to the edge gives the size of the edge's possible bias.  ``None`` when
        not measured (synthetic edges).
    left_wide_px, right_wide_px, left_wide_sigma_px, right_wide_sigma_px : ndarray or None
        The same edges from a wider window (``n_out_wide`` pixels outside,
        ``n_in_wide`` inside the rough edge pixel), which contains the whole
        transition when the edge is spread over the exposure and the pixel's
        height (near the ball's ends); noisier, used only there.
    left_wide_ok, right_wide_ok : ndarray of bool or None
        Usability of the wide-window edges (same rules).
    profile, profile_sigma : ndarray (n_lines, n_cols) or None
        The normalised profile ``p`` of every measured line over the
        region's columns and its 1-sigma (normalised units), for fits of the
        pixels themselves (the ball's faint ends); NaN where a pixel is
        saturated or belongs to another ball.
    profile_col0 : int
        Sensor pixel of ``profile[:, 0]``.
    profile_shade : ndarray (n_lines, n_cols) or None
        The brightness model's surface brightness of the ball at each pixel
        of ``profile`` (normalised units; 1 where not evaluated), for the
        fit's pixel model (``pixels`` of :class:`ballscan.solve.fit.FitSettings`),
        which multiplies the coverage by it (NaN: 1); None: 1 everywhere.
        Set by :func:`ballscan.measure.shading.shade_profile`.
    area_level, area_level_sigma : ndarray or None
        The brightness model's mean normalised level over the covered part of
        each line (``limb.line_levels`` of :func:`measure_edges`; NaN on the
        lines it was not evaluated on) and its relative 1-sigma: ``area_px /
        area_level`` is the line's covered length.  None without a model.
    left_matched, right_matched : ndarray of bool or None
        The narrow-window edges that :func:`ballscan.measure.matched.matched_edges` measured (the fit
        gives them ``FitSettings.matched_floor_px`` instead of
        ``edge_floor_px``); None: none (see :attr:`edges_method`).
    area_excluded : ndarray of bool or None
        Lines whose area the fit must not use although the ball is on them
        (their edges left out by :func:`without_edges`, or an edge on a
        limb of the other sign: the area adds both signs); None: none.
    """

    lines: np.ndarray
    t_s: np.ndarray
    left_px: np.ndarray
    right_px: np.ndarray
    left_sigma_px: np.ndarray
    right_sigma_px: np.ndarray
    left_ok: np.ndarray
    right_ok: np.ndarray
    area_px: np.ndarray
    area_sigma_px: np.ndarray
    centroid_px: np.ndarray
    level: np.ndarray
    peak: np.ndarray
    end_line: np.ndarray
    polarity: int = 1
    contrast_dn: float = 1.0
    flags: tuple[str, ...] = ()
    left_texture_px: np.ndarray | None = None
    right_texture_px: np.ndarray | None = None
    left_wide_px: np.ndarray | None = None
    right_wide_px: np.ndarray | None = None
    left_wide_sigma_px: np.ndarray | None = None
    right_wide_sigma_px: np.ndarray | None = None
    left_wide_ok: np.ndarray | None = None
    right_wide_ok: np.ndarray | None = None
    profile: np.ndarray | None = None
    profile_sigma: np.ndarray | None = None
    profile_col0: int = 0
    area_level: np.ndarray | None = None
    area_level_sigma: np.ndarray | None = None
    profile_shade: np.ndarray | None = None
    left_matched: np.ndarray | None = None
    right_matched: np.ndarray | None = None
    area_excluded: np.ndarray | None = None
    # the first pass's intermediates, for with_limb (None: not made by measure_edges)
    _pass: _EdgePass | None = field(default=None, compare=False, repr=False)

    @property
    def edges_method(self) -> str:
        """``"matched"`` where :func:`ballscan.measure.matched.matched_edges` measured any edge, else ``"window"`` (the local area estimate)."""
        flags = [f for f in (self.left_matched, self.right_matched) if f is not None]
        return "matched" if any(bool(f.any()) for f in flags) else "window"

    @property
    def n_edges(self) -> int:
        """Number of usable edges."""
        return int(self.left_ok.sum() + self.right_ok.sum())

    @property
    def signal(self) -> np.ndarray:
        """Lines whose peak shows the ball (edges measured or end line)."""
        return (self.left_ok | self.right_ok) | self.end_line


@dataclass(frozen=True)
class _EdgePass:
    """What :func:`measure_edges` computes before and besides the inner levels of ``limb``.

    The per-estimate arrays have ``4 n`` rows (``n`` lines each: narrow
    window left and right, wide window left and right, see ``quarters``) and
    are in box pixels; ``e``, ``var`` and ``L`` are the model-free edges,
    variances and levels.  ``usable`` holds every rule of an edge's usability
    but the plausibility of its level, ``run_ok`` the level run's own,
    ``limb_rows`` the rows ``limb`` may correct (signal, deep run inside the
    box), ``spoiled`` the lines whose area is not clean (cut, saturated or
    overlapped edge, or an edge on a limb of the other sign), ``common`` the fields of :class:`EdgeMeasurements` that
    ``limb`` does not change.  The other arrays are the arguments of
    :func:`_limb_levels`.
    """

    settings: EdgeSettings
    n_img: int
    c0: int
    quarters: tuple[slice, ...]
    has_signal: np.ndarray
    e: np.ndarray
    var: np.ndarray
    L: np.ndarray
    S: np.ndarray
    L_run: np.ndarray
    sl2: np.ndarray
    sw: np.ndarray
    n_win: np.ndarray
    win_first: np.ndarray
    win_last: np.ndarray
    lev: np.ndarray
    deep: np.ndarray
    limb_rows: np.ndarray
    pd: np.ndarray
    sd2: np.ndarray
    sgn: np.ndarray
    lines_abs: np.ndarray
    dlev: np.ndarray
    usable: np.ndarray
    run_ok: np.ndarray
    spoiled: np.ndarray
    common: _Unchanged
    excluded: np.ndarray | None = None


@dataclass(frozen=True)
class _Unchanged:
    """The fields of :class:`EdgeMeasurements` that ``limb`` does not change (see there)."""

    lines: np.ndarray
    t_s: np.ndarray
    area_px: np.ndarray
    area_sigma_px: np.ndarray
    centroid_px: np.ndarray
    peak: np.ndarray
    polarity: int
    contrast_dn: float
    flags: tuple[str, ...]
    profile: np.ndarray
    profile_sigma: np.ndarray
    profile_col0: int


def _as_columns(value: Any, n_lines: int, width: int, name: str) -> np.ndarray:
    """Broadcast a scalar, per-column (W,) or per-pixel (n_lines, W) array to (n_lines, W)."""
    a = np.asarray(value, dtype=float)
    if a.shape == (n_lines, width):
        # (already that shape: a view of it would only cost the broadcast's fixed time)
        return a
    if a.ndim == 0 or a.shape == (width,) or a.shape == (1, width):
        return np.broadcast_to(a, (n_lines, width))
    raise ValueError(f"{name}: expected a scalar, ({width},) or ({n_lines}, {width}) array, got shape {a.shape}")


def _region_pixels(region: Any, l0: int, l1: int, c0: int, c1: int) -> np.ndarray:
    """Boolean mask of a region (its mask, or its whole box) within the window ``[l0, l1) x [c0, c1)`` of the image.

    Only the window is allocated: the cost is that of the window, not of
    the image, however many other balls the image holds.
    """
    out = np.zeros((l1 - l0, c1 - c0), dtype=bool)
    r0, r1, q0, q1 = int(region.line_start), int(region.line_stop), int(region.col_start), int(region.col_stop)
    mask = getattr(region, "mask", None)
    m = np.ones((r1 - r0, q1 - q0), dtype=bool) if mask is None else np.asarray(mask, dtype=bool)
    # the part of the region's box (mask) inside the window
    a0, a1 = max(r0, l0), min(r0 + m.shape[0], l1)
    b0, b1 = max(q0, c0), min(q0 + m.shape[1], c1)
    if a0 < a1 and b0 < b1:
        out[a0 - l0 : a1 - l0, b0 - c0 : b1 - c0] = m[a0 - r0 : a1 - r0, b0 - q0 : b1 - q0]
    return out


def _smooth_lines(x: np.ndarray, n: int, degree: int) -> np.ndarray:
    """Smooth a per-line quantity: a robust polynomial in the line index.

    A polynomial of ``degree`` is fitted to the finite entries, entries more
    than 3 robust sigmas off are dropped and it is fitted again (twice); with
    fewer than ``3 (degree + 1)`` finite entries, a running median over ``n``
    lines is used instead.  NaN stays NaN.
    """
    if degree < 0:
        return _running_median(x, n)
    idx = np.flatnonzero(np.isfinite(x))
    if idx.size < 3 * (degree + 1):
        return _running_median(x, n)
    u = (idx - idx.mean()) / max(float(np.ptp(idx)), 1.0)
    y = x[idx]
    keep = np.ones(idx.size, dtype=bool)
    coef = np.zeros(degree + 1)
    for _ in range(3):
        coef = np.polynomial.polynomial.polyfit(u[keep], y[keep], degree)
        res = y - np.polynomial.polynomial.polyval(u, coef)
        mad = 1.4826 * float(median(np.abs(res[keep])))
        new = np.abs(res) <= 3.0 * max(mad, 1e-6)
        if new.sum() < 3 * (degree + 1) or np.array_equal(new, keep):
            break
        keep = new
    out = np.full(x.size, np.nan)
    out[idx] = np.polynomial.polynomial.polyval(u, coef)
    return out


def _limb_levels(limb, e, var0, L0, S, L_run, sl2, sw, n_win, win_first, win_last, lev, deep, pd, sd2, sgn, valid, lines_abs, m, tol):
    """Inner levels from a brightness model's profile (see ``limb`` of :func:`measure_edges`).

    The window's sum is ``S = L_eff * c`` with ``c`` the covered length and
    ``L_eff`` the mean level over it.  The data's ``L_eff`` is taken as the
    level run's ``L_run`` times the model's ratio ``L_eff / L_run`` (the
    model's window value per covered length over its level run's value), so
    the model supplies only the profile's shape (the limb's shading, the
    spread of the edge over the exposure) and the local level still comes
    from the pixels.  The model is evaluated on whole pixels (its
    ``pixel_coverage`` times the surface's brightness) with its mean edge
    placed at the model-free edge ``e``, and the mean edge moves from there
    by the difference between the model's covered length in the window and
    the data's ``S / L_eff``: ``inner - S / L_eff`` alone would be the mean
    edge only if the window held the whole ramp, and a spread edge's
    coverage reaches past its inner end (by a few hundredths of a pixel of
    coverage next to a ball's ends).  Two rounds, the second with the
    model at the first's edge (the level run sits in that tail).

    The model knows the shading, not the texture: where the data's ratio of
    the run inside the level run (``pd``) to the level run differs from the
    model's, evaluated at the new edge, by more than 3 sigma plus ``tol``
    (a seam or a felt patch), or the ratio leaves [0.5, 2] (the level rule
    of :func:`_finish` would reject the edge), the model-free estimate is
    kept.

    Parameters
    ----------
    limb : LimbProfile-like
        See :func:`measure_edges`; its ``rows`` give the model to the
        compiled loop (:func:`ballscan.measure._shading_kernels.limb_levels`), which
        evaluates the model as its ``pixel_coverage``, ``surface`` and
        ``__call__`` do.
    e, var0, L0 : ndarray (R,)
        Model-free edges (box pixels), their variances (px^2) and levels.
    S, L_run, sl2 : ndarray (R,)
        Window sums, level-run means and the level runs' variances
        (normalised units).
    sw : ndarray (R, n)
        Window pixels' sigmas (zero where padded).
    n_win, win_first, win_last : ndarray (R,)
        Window lengths and first (outermost) / last (innermost) pixels.
    lev, deep : ndarray (R, n_level)
        Level-run pixels and the run inside it (box pixels).
    pd, sd2 : ndarray (R,)
        Mean and variance of the run inside the level run.
    sgn : ndarray (R,)
        +1 for left edges, -1 for right edges.
    valid : ndarray of bool (R,)
        Rows to correct.
    lines_abs : ndarray of int (R,)
        Image line of each row.
    m : int
        Point samples per pixel of the model's brightness on the partly
        covered pixels.
    tol : float
        Texture tolerance (see :class:`EdgeSettings`).

    Returns
    -------
    edge, var, L : ndarray (R,)

    Raises
    ------
    GeometryError
        If the inverse distortion of a model ray does not converge.
    """
    edge, var, L = e.copy(), var0.copy(), L0.copy()
    rows = np.flatnonzero(valid & np.isfinite(e))
    if rows.size == 0:
        return edge, var, L
    # the window from its outermost pixel inwards, then the level run and
    # the run inside it, in one array (compiled)
    sg, px, kw = limb_pixels(rows, sgn, win_first, win_last, n_win, lev, deep)
    # the data's ratio of the run inside the level run to the level run, and
    # how far the model's may differ (texture, not shading, beyond)
    L_r, pd_r, sl2_r = L_run[rows], pd[rows], sl2[rows]
    with np.errstate(invalid="ignore", divide="ignore"):
        q_data = pd_r / L_r
        q_sig = np.sqrt(sd2[rows] / L_r**2 + sl2_r * pd_r**2 / L_r**4)
    edge[rows], var[rows], L[rows], rays_ok = limb_levels(
        sg, px, as_arg(n_win[rows], np.int64), kw, lev.shape[1], e[rows], var0[rows], L0[rows], S[rows], L_r, sl2_r,
        as_arg(sw[rows]), q_data, 3.0 * q_sig + tol, int(m), *limb.rows(lines_abs[rows], sg),
    )
    if not rays_ok:
        raise GeometryError("inverse distortion did not converge: coordinate outside the monotonic range of k1, k2")
    return edge, var, L


def _running_median(x: np.ndarray, n: int, blocks: int = 1) -> np.ndarray:
    """Median of ``x`` over a centred window of ``n`` entries, ignoring NaN (NaN where all are).

    With ``blocks``, of each of that many equal parts of ``x`` on its own
    (the windows end at the parts' ends).
    """
    if n <= 1 or x.size == 0:
        return x.copy()
    # the median of the finite entries (the mean of the middle two for an
    # even count), as np.nanmedian; compiled (_edge_kernels.running_medians)
    return running_medians(as_arg(x), int(blocks), int(n))


def measure_edges(
    data: np.ndarray,
    region: Any,
    background_dn: Any,
    noise_dn: Any,
    t_lines_s: np.ndarray,
    *,
    saturation_dn: float | None = None,
    others: Sequence[Any] = (),
    settings: EdgeSettings = EdgeSettings(),
    limb: Callable[[np.ndarray, np.ndarray, np.ndarray], tuple[np.ndarray, np.ndarray]] | None = None,
    blind_columns: Sequence[int] = (),
) -> EdgeMeasurements:
    """Measure both edges and the summed coverage on every line of one ball.

    Parameters
    ----------
    data : ndarray, shape (n_lines, W)
        The image in DN as stored (:attr:`ballscan.measure.images.LineImage.data`).
    region : BallRegion-like
        Any object with ``line_start, line_stop`` (exclusive), ``col_start,
        col_stop`` (exclusive), ``polarity`` (+1/-1), ``contrast_dn`` and
        optionally ``mask`` (bool box) and ``both_signs`` (a region of both
        signs, the only kind whose edges may move onto a limb of the other
        sign), e.g.
        :class:`ballscan.measure.detection.BallRegion`.
    background_dn : float or ndarray
        Background level, DN: scalar, per column ``(W,)`` or per pixel.
    noise_dn : float or ndarray
        Pixel noise 1-sigma, DN: scalar, per column or per pixel.
    t_lines_s : ndarray, shape (n_lines,)
        Centre time of each image line, seconds.
    saturation_dn : float, optional
        Pixels at or above it are clipped (their edges are unusable).
    others : sequence of BallRegion-like
        The other balls' regions: edges whose window meets one are unusable.
    settings : EdgeSettings
    limb : LimbProfile-like, optional
        The ball's brightness model across the left (side +1) or right (-1)
        edge of image lines, a :class:`ballscan.measure.shading.LimbProfile`:
        ``limb.rows(lines, sides)`` gives the model as the arguments of the
        compiled levels (:func:`ballscan.measure._shading_kernels.limb_levels`, which
        evaluates it as the profile's ``pixel_coverage``, ``surface`` and
        ``__call__`` do), ``limb.spread_px`` the model's edge spread per
        image line (pixels), which selects the narrow and wide windows to
        correct (``limb_narrow_max_px``, ``limb_wide_px``), and
        ``limb.line_levels(lines)`` (optional) the brightness of the ends'
        covered part.  When given, each
        edge's inner level is the level run times the model's ratio of the
        mean level over the covered part of the window to the level run's,
        and the edge is the model's mean edge moved by the difference
        between the data's covered length and the model's (see
        :func:`_limb_levels`), instead of the linear extrapolation of
        ``level_slope``.  :func:`with_limb` gives the same for edges already
        measured, without measuring them again.
    blind_columns : sequence of int
        Image columns whose values are not the scene's (a stuck column
        replaced by its neighbours' interpolation,
        :mod:`ballscan.measure.defects`): an edge whose window or level run
        holds one is unusable.

    Returns
    -------
    EdgeMeasurements
    """
    ps = _edge_pass(data, region, background_dn, noise_dn, t_lines_s, saturation_dn=saturation_dn, others=others, settings=settings, blind_columns=blind_columns)
    return _finish(ps, limb)


def with_limb(
    edges: EdgeMeasurements, limb: Callable[[np.ndarray, np.ndarray, np.ndarray], tuple[np.ndarray, np.ndarray]] | None
) -> EdgeMeasurements:
    """The edges of :func:`measure_edges` measured again with another profile model.

    Equal to calling :func:`measure_edges` with the same arguments as for
    ``edges`` and ``limb=limb`` (bit for bit; edges that :func:`without_edges`
    left out stay out), but only the inner levels and
    what follows from them are recomputed: the profile, the rough edges, the
    windows' sums, the level runs and the noise model of ``edges`` are
    reused (the fields that do not depend on ``limb``, e.g. ``profile``,
    are the same arrays as ``edges``').

    Parameters
    ----------
    edges : EdgeMeasurements
        Made by :func:`measure_edges` or by this function (with or without
        a ``limb``).
    limb : callable or None
        The profile model, as ``limb`` of :func:`measure_edges`; None gives
        the model-free edges.

    Returns
    -------
    EdgeMeasurements

    Raises
    ------
    ValueError
        If ``edges`` were not made by :func:`measure_edges` (e.g. built
        directly from synthetic edges).
    """
    if edges._pass is None:
        raise ValueError("edges: not made by measure_edges (no first pass to reuse)")
    return _finish(edges._pass, limb)


def without_edges(edges: EdgeMeasurements, left: np.ndarray, right: np.ndarray) -> EdgeMeasurements:
    """``edges`` with the given lines' left / right edges unusable (both windows), and those lines' areas kept out of the fit.

    For edges known not to be the ball's limb (dark texture at the limb,
    :func:`ballscan.solve.envelope.trim_inward`): such a line's area is
    short by the same texture, so it neither becomes an end line nor counts
    as a line beside the ball (:attr:`EdgeMeasurements.area_excluded`).
    Later passes of :func:`with_limb` keep the exclusion.

    Parameters
    ----------
    edges : EdgeMeasurements
        Made by :func:`measure_edges` without a ``limb`` (a limb's levels
        are not kept: pass :func:`with_limb` the result instead), or built
        directly (e.g. :func:`ballscan.solve.synthetic.synthetic_edges`:
        then only the usability flags and the lines' areas change).
    left, right : ndarray of bool (N,)
        One flag per measured line.

    Raises
    ------
    ValueError
        If the flags do not have one entry per line.
    """
    left, right = np.asarray(left, dtype=bool), np.asarray(right, dtype=bool)
    n = edges.t_s.size
    if left.shape != (n,) or right.shape != (n,):
        raise ValueError(f"left, right: need one flag per measured line ({n}), got {left.shape} and {right.shape}")
    out = left | right
    excluded = out if edges.area_excluded is None else edges.area_excluded | out
    ps = edges._pass
    if ps is None:
        wide = {} if edges.left_wide_ok is None else {"left_wide_ok": edges.left_wide_ok & ~left, "right_wide_ok": edges.right_wide_ok & ~right}
        return replace(edges, left_ok=edges.left_ok & ~left, right_ok=edges.right_ok & ~right, end_line=edges.end_line & ~out, area_excluded=excluded, **wide)
    usable = ps.usable.copy()
    for q, side in zip(ps.quarters, (left, right, left, right)):
        usable[q] &= ~side
    return _finish(replace(ps, usable=usable, spoiled=ps.spoiled | out, excluded=excluded), None)


@dataclass(frozen=True)
class _Box:
    """A ball's box (its lines +- ``margin_lines``, its columns +- ``pad_px``) and its normalised profile.

    ``profile`` is ``p = polarity (I - bg) / contrast_dn`` (about 0 outside
    the ball, 1 inside), ``profile_sigma`` the background's noise of ``p``
    (normalised units), ``per_column_noise`` whether that noise is the same
    on every line (a scalar or per-column noise), ``saturated_px`` and
    ``other_px`` the box's clipped pixels and the pixels of other balls
    (dilated by one pixel along the line).
    """

    n_img: int
    width_px: int
    c0: int
    c1: int
    lines: np.ndarray
    t_s: np.ndarray
    polarity: int
    contrast_dn: float
    profile: np.ndarray
    profile_sigma: np.ndarray
    per_column_noise: bool
    saturated_px: np.ndarray
    other_px: np.ndarray
    both_signs: bool = False


@dataclass(frozen=True)
class _RoughEdges:
    """Per line of a box: the profile's peak, whether it shows the ball, the rough edge pixels (box columns) and each edge's sign.

    ``sign_left`` and ``sign_right`` are +1 where the limb has the ball's
    sign and -1 where it has the other (darker than the backdrop on a
    bright ball); None where every edge has the ball's sign.
    """

    peak: np.ndarray
    has_signal: np.ndarray
    k_left: np.ndarray
    k_right: np.ndarray
    sign_left: np.ndarray | None = None
    sign_right: np.ndarray | None = None


@dataclass(frozen=True)
class _WindowSums:
    """The window and level-run sums of every edge estimate (:func:`ballscan.measure._edge_kernels.edge_windows`, in its order).

    Rows ``4 n`` (narrow window left and right, wide window left and
    right): ``S`` the window sums, ``sw`` the window pixels' sigmas (0 beyond
    a shorter window) and ``sw2`` their sums of squares, ``L_run`` and
    ``sl2`` the level run's mean and variance, ``pl0``, ``pl1``, ``sl0``,
    ``sl1`` its first and last pixels' values and sigmas, ``pd``, ``sd2``,
    ``pdd``, ``sdd2`` the deep and deeper runs' means and variances,
    ``win_first``, ``win_last``, ``n_win`` the window's outermost and
    innermost pixels and length, ``lev``, ``deep`` the level run's and deep
    run's pixels (unclipped), ``sgn`` +1 (left) / -1 (right), ``lo``, ``hi``
    the extreme pixels of window and level run, ``inside_box`` whether they
    lie in the box, ``saturated`` and ``overlapping`` whether a window or
    level pixel is saturated or another ball's.
    """

    S: np.ndarray
    sw: np.ndarray
    sw2: np.ndarray
    L_run: np.ndarray
    sl2: np.ndarray
    pl0: np.ndarray
    pl1: np.ndarray
    sl0: np.ndarray
    sl1: np.ndarray
    pd: np.ndarray
    sd2: np.ndarray
    pdd: np.ndarray
    sdd2: np.ndarray
    win_first: np.ndarray
    win_last: np.ndarray
    n_win: np.ndarray
    lev: np.ndarray
    deep: np.ndarray
    sgn: np.ndarray
    lo: np.ndarray
    hi: np.ndarray
    inside_box: np.ndarray
    saturated: np.ndarray
    overlapping: np.ndarray


@dataclass(frozen=True)
class _WindowEdges:
    """The model-free inner levels ``L``, edges ``e`` (box pixels) and their variances ``var`` (px^2), one per row of :class:`_WindowSums`."""

    L: np.ndarray
    e: np.ndarray
    var: np.ndarray


@dataclass(frozen=True)
class _Usability:
    """Which edge estimates are usable (all but the level's plausibility), the lines whose area is spoiled, and the ball's flags."""

    usable: np.ndarray
    spoiled: np.ndarray
    flags: tuple[str, ...]


def _box(
    data: np.ndarray,
    region: Any,
    background_dn: Any,
    noise_dn: Any,
    t_lines_s: np.ndarray,
    saturation_dn: float | None,
    others: Sequence[Any],
    s: EdgeSettings,
) -> _Box:
    """The region's box and its normalised profile (arguments of :func:`measure_edges`), checked."""
    data = np.asarray(data, dtype=float)
    if data.ndim != 2:
        raise ValueError(f"data: expected a 2-D (n_lines, W) array, got shape {data.shape}")
    n_img, W = data.shape
    t_lines_s = np.asarray(t_lines_s, dtype=float)
    if t_lines_s.shape != (n_img,):
        raise ValueError(f"t_lines_s: expected {n_img} times, got shape {t_lines_s.shape}")
    contrast = abs(float(region.contrast_dn))
    if not np.isfinite(contrast) or contrast <= 0:
        raise ValueError(f"region.contrast_dn: must be non-zero and finite, got {region.contrast_dn!r}")
    pol = 1 if float(region.polarity) >= 0 else -1

    l0 = max(int(region.line_start) - s.margin_lines, 0)
    l1 = min(int(region.line_stop) + s.margin_lines, n_img)
    c0 = max(int(region.col_start) - s.pad_px, 0)
    c1 = min(int(region.col_stop) + s.pad_px, W)
    if l1 <= l0 or c1 <= c0:
        raise ValueError("region: empty line or column range")
    lines = np.arange(l0, l1)
    n, w = lines.size, c1 - c0

    bg = _as_columns(background_dn, n_img, W, "background_dn")[l0:l1, c0:c1]
    sd = _as_columns(noise_dn, n_img, W, "noise_dn")[l0:l1, c0:c1]
    raw = data[l0:l1, c0:c1]
    p = pol * (raw - bg) / contrast
    # noise of p, normalised units
    per_column = sd.strides[0] == 0
    if per_column:
        # a scalar or per-column noise: one line's, repeated
        sp = np.empty((n, w))
        sp[:] = np.maximum(sd[0], 1e-12) / contrast
    else:
        sp = np.maximum(sd, 1e-12) / contrast
    sat = raw >= saturation_dn if saturation_dn is not None else np.zeros_like(raw, dtype=bool)
    other = np.zeros((n, w), dtype=bool)
    for o in others:
        om = _region_pixels(o, l0, l1, c0, c1)
        # one pixel of dilation along the line: a neighbour's blur reaches it
        other |= om | np.roll(om, 1, axis=1) | np.roll(om, -1, axis=1)
    return _Box(
        n_img=n_img, width_px=W, c0=c0, c1=c1, lines=lines, t_s=t_lines_s[lines], polarity=pol, contrast_dn=contrast,
        profile=p, profile_sigma=sp, per_column_noise=per_column, saturated_px=sat, other_px=other,
        both_signs=bool(getattr(region, "both_signs", False)),
    )


#: pixels beyond a rough edge over which a limb's sign may change (its
#: brightness passing the backdrop's) before a run of the other sign starts
_OTHER_SIGN_GAP_PX = 2


def _rough_edges(box: _Box, s: EdgeSettings) -> _RoughEdges:
    """The lines that show the ball and their rough edge pixels, walked out onto a shaded limb."""
    p, sp = box.profile, box.profile_sigma
    peak = p.max(axis=1)
    if box.per_column_noise:
        # every line has the same median
        noise_row = np.full(p.shape[0], float(median(sp[0])))
    else:
        noise_row = np.median(sp, axis=1)
    has_signal = peak > s.min_snr * noise_row
    # the first and last pixels at find_fraction of the peak (compiled)
    k_left, k_right = rough_edges(p, peak, float(s.find_fraction))
    # A shaded limb can be darker than a fraction of a bright seam's peak:
    # walk outwards while the next pixel still holds find_fraction of its
    # inner neighbour (and is significant), so that the window sits on the
    # ball's real edge (compiled, line by line).
    floor_p = s.walk_snr * noise_row
    k_left, k_right = walk_edges(p, k_left, k_right, as_arg(has_signal, np.bool_), as_arg(floor_p), float(s.find_fraction), int(s.max_walk_px))
    if not box.both_signs:
        return _RoughEdges(peak=peak, has_signal=has_signal, k_left=k_left, k_right=k_right)
    # a limb of the other sign beyond the edges, on the lines whose part of
    # that sign is deep enough (compiled)
    min_peak = np.maximum(s.min_snr * noise_row, s.other_sign_depth)
    k_left, k_right, sl, sr, has_signal = other_sign_edges(
        -p, k_left, k_right, as_arg(has_signal, np.bool_), as_arg(min_peak), as_arg(floor_p), float(s.find_fraction), int(s.max_walk_px),
        _OTHER_SIGN_GAP_PX, int(s.other_sign_run_px),
    )
    if np.all(sl > 0) and np.all(sr > 0):
        return _RoughEdges(peak=peak, has_signal=has_signal, k_left=k_left, k_right=k_right)
    return _RoughEdges(peak=peak, has_signal=has_signal, k_left=k_left, k_right=k_right, sign_left=sl, sign_right=sr)


def _ball_noise(box: _Box, rough: _RoughEdges, s: EdgeSettings) -> np.ndarray:
    """The profile's noise with the ball's shot noise (``ball_noise`` of :class:`EdgeSettings`), normalised units.

    The background's noise understates the ball's: the ball's pixel noise is
    estimated from second differences inside the segments and grows
    linearly with the signal.  ``box.profile_sigma`` itself where it is off
    or cannot be estimated.
    """
    p, sp = box.profile, box.profile_sigma
    if not s.ball_noise:
        return sp
    # the pixels 3 or more inside both rough edges whose neighbours are
    # too: their second differences, values and noise
    vals, p_both, sp_both, per_col = inner_differences(p, as_arg(sp), rough.k_left, rough.k_right, rough.has_signal)
    if vals.size < 50:
        return sp
    sig_in = 1.4826 * float(median(np.abs(vals - median(vals)))) / math.sqrt(6.0)
    p_in = float(median(p_both))
    if box.per_column_noise:
        # every line has the same per-column noise: the median over
        # the pixels is a median of the columns weighted by their counts
        sig_bg = weighted_median(sp[0], per_col)
    else:
        sig_bg = float(median(sp_both))
    if p_in > 0 and sig_in > sig_bg:
        # each pixel's signal for its noise from its column neighbours,
        # not its own value (compiled: see _edge_kernels.shot_noise)
        return shot_noise(p, as_arg(sp), sig_in**2 - sig_bg**2, p_in)
    return sp


def _window_sums(p: np.ndarray, sp: np.ndarray, box: _Box, rough: _RoughEdges, n_out: np.ndarray, n_in: np.ndarray, s: EdgeSettings) -> _WindowSums:
    """The window and level-run sums of every edge estimate, each edge on its limb's sign (:func:`ballscan.measure._edge_kernels.edge_windows`).

    An edge of the other sign is measured on the line's profile times -1,
    so that its window, level and the rules on them read as a limb of the
    ball's sign; the shading model's profile of that side is of the other
    sign as well, and only its ratios enter (:func:`_limb_levels`).
    """
    def sums(prof: np.ndarray) -> _WindowSums:
        return _WindowSums(
            *edge_windows(prof, as_arg(sp), as_arg(box.saturated_px, np.bool_), box.other_px, rough.k_left, rough.k_right, n_out, n_in, int(s.n_level))
        )

    if rough.sign_left is None:
        return sums(p)
    left = sums(p * rough.sign_left[:, None].astype(float))
    right = sums(p * rough.sign_right[:, None].astype(float))
    # rows: per window variant the left edges of the n lines, then the right ones
    is_left = left.sgn > 0
    return _WindowSums(*(np.where(is_left.reshape((-1,) + (1,) * (a.ndim - 1)), a, b) for a, b in zip(vars(left).values(), vars(right).values())))


def _window_edges(ws: _WindowSums, hs4: np.ndarray, n_in: np.ndarray, s: EdgeSettings, quarters: tuple[slice, ...]) -> _WindowEdges:
    """The inner levels extrapolated to the limb (``level_slope``), the edges from the windows' uncovered lengths and their variances."""
    nv = len(quarters)
    # relative level gradient, median-filtered along the lines (shading is
    # smooth from line to line, felt texture and noise are not):
    # gradient per pixel across the level run (inwards positive), towards
    # the covered part of the edge pixel (about `dist` pixels outwards), and
    # the noise of its median of slope_lines lines (compiled)
    raw_rel, rel_var, rel_sig = level_gradients(
        ws.pl0, ws.pl1, ws.pd, ws.L_run, ws.sl0, ws.sl1, ws.sd2, ws.sl2, hs4, n_in, int(s.n_level), int(s.slope_lines)
    )
    if s.slope_degree < 0:
        # (_smooth_lines' running median, of every side in one call)
        rel = _running_median(raw_rel, s.slope_lines, nv)
    else:
        rel = np.concatenate([_smooth_lines(raw_rel[q], s.slope_lines, s.slope_degree) for q in quarters])
    # Only a side whose gradient stands out of its noise is corrected (an
    # unshaded ball keeps the plain level and its noise).  The decision
    # is taken once per side (and window), not per line: shrinking each
    # line's correction by its noise would bias noisy edges inwards.
    # (compiled: per side and window, the mean of |rel| / rel_sig over the
    # lines with signal, NaN as 0; the unshaded sides' rel set to 0)
    rel = shaded_sides(rel, rel_sig, hs4 & (rel_sig > 0), nv, float(s.slope_threshold))
    kap = s.level_slope
    L, e, var = window_edges(
        rel, rel_var, ws.L_run, ws.S, ws.sw2, ws.sl2, ws.n_win, ws.win_first, ws.win_last, ws.sgn, float(kap), float(kap**2)
    )
    return _WindowEdges(L=L, e=e, var=var)


def _usability(box: _Box, rough: _RoughEdges, ws: _WindowSums, hs4: np.ndarray, s: EdgeSettings, quarters: tuple[slice, ...]) -> _Usability:
    """Every rule of an edge's usability but its level's, the lines whose area is spoiled, and the flags of the ball (see the module docstring)."""
    c0, W = box.c0, box.width_px
    k_left, k_right, has_signal = rough.k_left, rough.k_right, rough.has_signal
    abs_lo, abs_hi = ws.lo + c0, ws.hi + c0
    at_sensor_end = (abs_lo <= 0) | (abs_hi >= W - 1) | ~ws.inside_box
    usable = hs4 & ~at_sensor_end & ~ws.saturated & ~ws.overlapping
    # both windows and level runs must fit in the segment without crossing
    span_needed = 2 * (s.n_in + s.n_level) + 1
    long_enough = (k_right - k_left) >= span_needed
    # wide windows for lines whose edge is spread over the exposure / pixel height
    long_wide = (k_right - k_left) >= 2 * (s.n_in_wide + s.n_level) + 1
    usable &= np.concatenate([long_enough, long_enough, long_wide, long_wide])
    endL, endR, satL, satR, ovL, ovR = (a[q] & has_signal for a in (at_sensor_end, ws.saturated, ws.overlapping) for q in quarters[:2])

    p, sat, other, w = box.profile, box.saturated_px, box.other_px, box.c1 - box.c0
    flags = []
    if np.any(endL | endR) or c0 == 0 and np.any(has_signal & (k_left <= 0)) or box.c1 == W and np.any(has_signal & (k_right >= w - 1)):
        flags.append("cut_sensor_end")
    # (the pixel tests only where a pixel is saturated or another ball's)
    if np.any(satL | satR) or sat.any() and np.any(sat & (p > 0.5)):
        flags.append("saturated")
    if np.any(ovL | ovR) or other.any() and np.any(other & (p > 0.5)):
        flags.append("overlap")
    return _Usability(usable=usable, spoiled=endL | endR | satL | satR | ovL | ovR, flags=tuple(flags))


def _windows_meet(lo: np.ndarray, hi: np.ndarray, columns: np.ndarray) -> np.ndarray:
    """Whether each estimate's window and level run (box columns ``lo`` to ``hi``) hold one of ``columns`` (box columns)."""
    meet = np.zeros(lo.shape, dtype=bool)
    for c in columns:
        meet |= (lo <= c) & (c <= hi)
    return meet


def _edge_pass(
    data: np.ndarray,
    region: Any,
    background_dn: Any,
    noise_dn: Any,
    t_lines_s: np.ndarray,
    *,
    saturation_dn: float | None,
    others: Sequence[Any],
    settings: EdgeSettings,
    blind_columns: Sequence[int] = (),
) -> _EdgePass:
    """Everything of :func:`measure_edges` that does not depend on ``limb`` (same parameters)."""
    s = settings
    box = _box(data, region, background_dn, noise_dn, t_lines_s, saturation_dn, others, s)
    rough = _rough_edges(box, s)
    p, sp = box.profile, _ball_noise(box, rough, s)
    n, w = p.shape

    # Every edge estimate at once: for each window (narrow, then wide) the
    # left edges (windows pointing inwards with sign +1), then the right
    # edges (sign -1), n rows each.  Windows shorter than the longest are
    # padded with their last pixel, masked out of the sums.
    variants = ((s.n_out, s.n_in), (s.n_out_wide, s.n_in_wide))
    nv = 2 * len(variants)
    quarters = tuple(slice(q * n, (q + 1) * n) for q in range(nv))
    hs4 = np.concatenate([rough.has_signal] * nv)
    n_in = np.array([v[1] for v in variants], dtype=np.int64)
    n_out = np.array([v[0] for v in variants], dtype=np.int64)
    # the windows' and runs' pixels and sums (compiled)
    ws = _window_sums(p, sp, box, rough, n_out, n_in, s)
    we = _window_edges(ws, hs4, n_in, s, quarters)
    use = _usability(box, rough, ws, hs4, s, quarters)
    usable = use.usable & ~_windows_meet(ws.lo, ws.hi, np.asarray(blind_columns, dtype=np.int64) - box.c0)
    spoiled, excluded = use.spoiled, None
    if rough.sign_left is not None:
        # a line's summed coverage adds the limb's two signs: not its area
        excluded = (rough.sign_left < 0) | (rough.sign_right < 0)
        spoiled = spoiled | excluded
    # texture indicator from pixels the edge does not use (the deep run and
    # the run inside it, pdd and sdd2), so that its noise is independent of
    # the edge's: a weight correlated with the edge's own error would bias the fit
    dlev = np.abs(ws.pd - ws.pdd) - np.sqrt(ws.sd2 + ws.sdd2)
    # summed coverage: over the segment +- 3 px where the ball is seen, else
    # the whole box (compiled: its sums, sigma and centroid in one pass)
    area, area_sig, centroid = line_coverage(p, sp, rough.k_left, rough.k_right, rough.has_signal, int(box.c0))
    deep = ws.deep
    return _EdgePass(
        settings=s,
        n_img=box.n_img,
        c0=box.c0,
        quarters=quarters,
        has_signal=rough.has_signal,
        e=we.e,
        var=we.var,
        L=we.L,
        S=ws.S,
        L_run=ws.L_run,
        sl2=ws.sl2,
        sw=ws.sw,
        n_win=ws.n_win,
        win_first=ws.win_first,
        win_last=ws.win_last,
        lev=ws.lev,
        deep=deep,
        # (a run's pixels step by one from its first to its last: those are its extremes)
        limb_rows=hs4 & (np.minimum(deep[:, 0], deep[:, -1]) >= 0) & (np.maximum(deep[:, 0], deep[:, -1]) < w),
        pd=ws.pd,
        sd2=ws.sd2,
        sgn=ws.sgn,
        lines_abs=np.concatenate([box.lines] * nv),
        dlev=np.maximum(dlev, 0.0),
        usable=usable,
        run_ok=ws.L_run > 3.0 * np.sqrt(ws.sl2),
        spoiled=spoiled,
        excluded=excluded,
        common=_Unchanged(
            lines=box.lines,
            t_s=box.t_s,
            area_px=area,
            area_sigma_px=area_sig,
            centroid_px=centroid,
            peak=rough.peak,
            polarity=box.polarity,
            contrast_dn=box.contrast_dn,
            flags=use.flags + (("both_signs",) if excluded is not None else ()),
            profile=np.where(box.saturated_px | box.other_px, np.nan, p),
            profile_sigma=sp,
            profile_col0=int(box.c0),
        ),
    )


def _finish(ps: _EdgePass, limb: Callable[..., tuple[np.ndarray, np.ndarray]] | None) -> EdgeMeasurements:
    """The edges of a first pass, with the inner levels of ``limb`` where given (see :func:`measure_edges`)."""
    s = ps.settings
    e, var, L, S, n_win = ps.e, ps.var, ps.L, ps.S, ps.n_win
    area_level = area_level_sigma = None
    if limb is not None:
        if not callable(getattr(limb, "rows", None)):
            raise ValueError("limb: needs rows (see measure_edges; e.g. a ballscan.measure.shading.LimbProfile)")
        spread = getattr(limb, "spread_px", None)
        if spread is None or np.shape(spread) != (ps.n_img,):
            raise ValueError(f"limb: needs a spread_px array of one entry per image line ({ps.n_img}), got {None if spread is None else np.shape(spread)}")
        line_spread = np.asarray(spread)[ps.common.lines]
        narrow = line_spread < s.limb_narrow_max_px
        wide = (line_spread >= s.limb_wide_px[0]) & (line_spread <= s.limb_wide_px[1])
        wanted = np.concatenate([narrow, narrow, wide, wide])
        e, var, L = _limb_levels(
            limb, e, var, L, S, ps.L_run, ps.sl2, ps.sw, n_win, ps.win_first, ps.win_last, ps.lev, ps.deep, ps.pd, ps.sd2,
            ps.sgn, ps.limb_rows & wanted, ps.lines_abs, s.limb_samples, s.limb_texture_tol,
        )
    # the usable edges (their levels plausible), the lines' edges, sigmas,
    # textures and levels, and the faint/short lines whose area is clean
    # (the fit uses their area instead of edges), in one compiled loop
    ok_all, edge, sig, tex, level, end_line = finished_edges(
        e, var, L, S, n_win, ps.dlev, ps.run_ok, ps.L_run, ps.usable, ps.has_signal, ps.spoiled, int(ps.c0)
    )
    okL, okR, okLw, okRw = (ok_all[q] for q in ps.quarters)
    has_signal = ps.has_signal
    if limb is not None and hasattr(limb, "line_levels"):
        # the brightness of the ends' covered part (their area's divisor)
        line_spread = np.asarray(limb.spread_px)[ps.common.lines]
        # not where a pixel of the line is saturated or another ball's (NaN in
        # the profile): its area is not the ball's coverage times a level
        clean = finite_rows(ps.common.profile)
        want = np.flatnonzero(
            has_signal & clean & np.isfinite(line_spread) & ((line_spread >= s.limb_area_min_spread_px) | ~(okL & okR))
        )
        area_level = np.full(has_signal.size, np.nan)
        area_level_sigma = np.full(has_signal.size, np.nan)
        lev_a, rel_a = limb.line_levels(ps.common.lines[want])
        area_level[want], area_level_sigma[want] = lev_a, rel_a
    return EdgeMeasurements(
        left_px=edge[0],
        right_px=edge[1],
        left_sigma_px=sig[0],
        right_sigma_px=sig[1],
        left_ok=okL,
        right_ok=okR,
        level=level,
        end_line=end_line,
        left_texture_px=tex[0],
        right_texture_px=tex[1],
        left_wide_px=edge[2],
        right_wide_px=edge[3],
        left_wide_sigma_px=sig[2],
        right_wide_sigma_px=sig[3],
        left_wide_ok=okLw,
        right_wide_ok=okRw,
        area_level=area_level,
        area_level_sigma=area_level_sigma,
        area_excluded=ps.excluded,
        _pass=ps,
        **vars(ps.common),
    )
