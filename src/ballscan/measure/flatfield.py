"""Column gains (fixed-pattern PRNU) measured on the ball's own interior.

A line-scan sensor's pixels differ in gain by about a percent
(photo-response non-uniformity, PRNU) unless the camera corrects them
(flat-field).  The detector's per-column background absorbs each column's
gain on the background, but not on the ball: there column ``j`` reads
``bg_j + g_j s`` for a ball signal ``s``, an error that repeats on every
line whose edge sits in that column.  The window edges
(:func:`ballscan.measure.edges.measure_edges`) take the ball's level from the line
itself and are hurt less than the matched edges
(:func:`ballscan.measure.matched.matched_edges`), which take it from the shading model:
on a sensor with 0.8 % PRNU those left the position sigmas about 2x too
small.  :func:`column_gains` measures how much the columns' gains scatter, so
that the estimator uses the matched edges only on a flat-fielded sensor.

Each pixel well inside the ball is divided by its line's median, each
column's gain is the median over its lines, what varies smoothly across the
columns (shading, a texture's large-scale pattern) is removed by a local
quadratic across 15 columns, and the scatter that remains beyond the measurement noise is the
gains' (robust method of moments).  On 8-bit images of the Fig. 5 ball it
resolves a PRNU of a few tenths of a percent (a flat sensor reads up to about
0.002).  A ball with fewer than 8 interior lines or 15 measurable columns
(about 17 px across) reads NaN: not measured.
Dividing the measured gains out of the image does not help the window edges:
the columns a ball's edges dwell on longest are its outermost, which are
never deep inside it.  The matched edges are measured on the image with the
gains divided out (:func:`flat_fielded`), each carrying the gain error that
remains in its edge pixel (:attr:`ColumnGains.gain_sigma`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cache

import numpy as np

from ..compiled import as_arg
from ._flatfield_kernels import median_deviations, sorted_medians
from .robust import median

__all__ = ["ColumnGains", "column_gains", "flat_fielded"]

# a column's gain needs at least this many interior lines (a median of fewer
# is too noisy to be worth the shrinkage estimate's help)
_MIN_LINES = 8
# interior pixels: at least this many ball pixels of the detector's mask on
# each side within the line (keeps the partially covered limb and the steep
# part of a shaded limb out)
_INSET_PX = 2
# local quadratic across the columns that removes the smooth part (odd; a
# running median flattens a steep smooth gradient and takes the gains with it)
_TREND_COLS = 15
# 1.4826 MAD = sigma; the variance of a median of n normal values is pi/2 sigma^2/n
_MAD_SIGMA = 1.4826
_MEDIAN_VAR = np.pi / 2.0


def _edge_projection(n: int, degree: int, half: int) -> np.ndarray:
    """The least-squares polynomial of ``degree`` through ``n`` points, evaluated at its first ``half`` points: a (half, n) matrix."""
    v = np.vander(np.arange(n, dtype=float), degree + 1)
    return v[:half] @ np.linalg.pinv(v)


@cache
def _trend_filter() -> tuple[np.ndarray, np.ndarray, float]:
    """``scipy.signal.savgol_filter(x, _TREND_COLS, 2, mode="interp")`` as a fixed linear filter: ``(coefficients, edge projection, leak)``.

    The centre coefficients of a quadratic Savitzky-Golay window of
    ``2 m + 1`` points are ``(3 (3 m^2 + 3 m - 1) - 15 i^2) / ((2 m - 1)
    (2 m + 1) (2 m + 3))`` for ``i = -m .. m`` (``scipy.signal.savgol_coeffs``
    gives them to rounding; scipy.signal takes most of a second to import);
    the edges are the least-squares quadratic through the first or last
    window.  ``leak`` is the fraction of a white (column-independent) gain
    pattern's variance that the trend takes.
    """
    m = _TREND_COLS // 2
    i = np.arange(-m, m + 1, dtype=float)
    coef = (3.0 * (3 * m * m + 3 * m - 1) - 15.0 * i * i) / ((2 * m - 1) * (2 * m + 1) * (2 * m + 3))
    return coef, _edge_projection(_TREND_COLS, 2, m), float(np.sum(coef**2))


# a column whose ratio to the trend is off by more than this many sigmas
# (the gains' scatter and its measurement's noise) is defective, not a gain
_DEFECT_SIGMAS = 5.0
# at most this many of them per ball
_MAX_DEFECTS = 8
# the sigma of that test at least this (relative gain)
_DEFECT_FLOOR = 1e-3


def _symmetric_filter(x: np.ndarray, coef: np.ndarray) -> np.ndarray:
    """``scipy.ndimage.convolve1d(x, coef, mode="constant")`` for a symmetric ``coef`` of odd length, bit for bit.

    Each output is ``x[i] c[m] + sum over d = m .. 1 of (x[i - d] + x[i + d]) c[m - d]``,
    summed in that order, as ``scipy.ndimage`` does for a symmetric filter
    (zeros beyond the ends); computed here across all ``i`` at once, which
    spares the batch path ``scipy.ndimage``'s import (about 50 ms).
    """
    m = coef.size // 2
    n = x.size
    xp = np.zeros(n + 2 * m)
    xp[m : m + n] = x
    y = xp[m : m + n] * coef[m]
    for d in range(m, 0, -1):
        y += (xp[m - d : m - d + n] + xp[m + d : m + d + n]) * coef[m - d]
    return y


def _trend(x: np.ndarray) -> np.ndarray:
    """``savgol_filter(x, _TREND_COLS, 2, mode="interp")`` (the edges to rounding; ``x`` at least ``_TREND_COLS`` long)."""
    coef, edge, _ = _trend_filter()
    y = _symmetric_filter(x, coef)
    h = _TREND_COLS // 2
    y[:h] = edge @ x[:_TREND_COLS]
    y[-h:] = (edge @ x[::-1][:_TREND_COLS])[::-1]
    return y


@dataclass(frozen=True)
class ColumnGains:
    """Relative gains of a ball's columns, as measured on its interior.

    Attributes
    ----------
    col_start : int
        Sensor pixel of ``gain[0]``.
    gain : ndarray (n_cols,)
        Estimated relative gain of each column (1 where not measured),
        shrunk towards 1 by :attr:`prnu_sigma`.
    n_lines : ndarray of int (n_cols,)
        Interior lines that measured each column.
    prnu_sigma : float
        Estimated relative spread of the columns' gains about their smooth
        trend (0 when it does not exceed the measurement noise; NaN when the
        ball shows too few interior lines or columns to measure it).
    n_columns : int
        Columns with a measurement.
    gain_sigma : ndarray (n_cols,) or None
        1-sigma of each column's gain about ``gain`` (the shrinkage
        estimate's posterior: ``prnu_sigma`` where not measured); None where
        ``prnu_sigma`` is NaN.
    """

    col_start: int
    gain: np.ndarray
    n_lines: np.ndarray
    prnu_sigma: float
    n_columns: int
    gain_sigma: np.ndarray | None = None

    def residual_sigma(self, cols: np.ndarray) -> np.ndarray:
        """``gain_sigma`` at sensor pixels ``cols`` (``prnu_sigma`` outside the box; NaN if not measured)."""
        cols = np.asarray(cols, dtype=int)
        if self.gain_sigma is None:
            return np.full(cols.shape, math.nan)
        k = cols - self.col_start
        inside = (k >= 0) & (k < self.gain_sigma.size)
        return np.where(inside, self.gain_sigma[np.clip(k, 0, self.gain_sigma.size - 1)], self.prnu_sigma)


def _masked_median(values: np.ndarray, mask: np.ndarray, axis: int) -> np.ndarray:
    """Median of ``values`` where ``mask`` along ``axis`` (0 or 1; NaN where none); np.median's value, by one sort.

    The masked values sort first with inf in the other places, and the
    middle ranks of each line's (or column's) count are picked in one
    compiled loop (:func:`ballscan.measure._flatfield_kernels.sorted_medians`).
    """
    mask = as_arg(mask, np.bool_)
    return sorted_medians(as_arg(np.sort(np.where(mask, values, np.inf), axis=axis)), mask, int(axis))


def _column_median_mad(values: np.ndarray, mask: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``_masked_median(values, mask, 0)`` and the median of ``|values - it|`` where ``mask`` (each column's), by one sort.

    The deviations' median comes from the sorted values themselves
    (:func:`ballscan.measure._flatfield_kernels.median_deviations`); only where a masked value
    is not finite are the deviations sorted as they are.
    """
    # (column by column along the transposed box: the columns of a box
    # indexed by its columns are contiguous)
    mask_t = as_arg(mask.T, np.bool_)
    med, mad, exact = median_deviations(as_arg(np.sort(np.where(mask_t, values.T, np.inf), axis=1)), mask_t)
    if not exact:
        mad = _masked_median(np.abs(values - med[None, :]), mask, axis=0)
    return med, mad


def _inset(mask: np.ndarray, k: int) -> np.ndarray:
    """Pixels of ``mask`` with ``k`` mask pixels on either side within their line (outside the box is not mask).

    ``scipy.ndimage.binary_erosion`` by a ``(1, 2 k + 1)`` line with
    ``border_value=0``, as ``2 k + 1`` shifted ands (a tenth of its fixed
    cost on a ball's box).
    """
    n = mask.shape[1]
    p = np.zeros((mask.shape[0], n + 2 * k), dtype=bool)
    p[:, k : k + n] = mask
    out = mask.copy()
    for d in range(2 * k + 1):
        out &= p[:, d : d + n]
    return out


def column_gains(
    data: np.ndarray,
    background: np.ndarray,
    mask: np.ndarray,
    line_start: int,
    col_start: int,
    polarity: int,
    saturation_dn: float | None = None,
) -> ColumnGains:
    """Measure the columns' gains on a ball's interior.

    Parameters
    ----------
    data, background : ndarray (n_lines, width)
        The image and the detector's background at every pixel, DN.
    mask : ndarray of bool (box_lines, box_cols)
        The detector's ball pixels of the region's box
        (:attr:`ballscan.measure.detection.BallRegion.mask`).
    line_start, col_start : int
        Image line and sensor pixel of ``mask[0, 0]``.
    polarity : int
        +1 for a ball brighter than the background, -1 for a darker one.
    saturation_dn : float, optional
        Pixels at or above it are not used.

    Returns
    -------
    ColumnGains
        For the box's columns; ``prnu_sigma`` NaN when fewer than 8 lines or
        15 columns can be measured (a small ball: not measured is not flat).

    Raises
    ------
    ValueError
        If ``polarity`` is not +1 or -1.
    """
    if polarity not in (1, -1):
        raise ValueError(f"polarity: must be +1 or -1, got {polarity!r}")
    n_l, n_c = mask.shape
    ls = slice(line_start, line_start + n_l)
    cs = slice(col_start, col_start + n_c)
    raw = data[ls, cs]
    s = polarity * (raw - background[ls, cs])
    inner = _inset(np.asarray(mask, dtype=bool), _INSET_PX)
    if saturation_dn is not None:
        inner &= raw < saturation_dn
    none = ColumnGains(col_start, np.ones(n_c), np.zeros(n_c, dtype=int), math.nan, 0)
    # a line's level from its own interior: the ball's brightness changes from
    # line to line (shading, texture, a partial exposure), the gains do not
    rows = inner.sum(axis=1) >= 2 * _INSET_PX + 1
    if rows.sum() < _MIN_LINES:
        return none
    inner = inner[rows]
    s = s[rows]
    level = _masked_median(s, inner, axis=1)
    inner &= (level > 0)[:, None]
    r = s / np.where(level > 0, level, 1.0)[:, None]
    n = inner.sum(axis=0)
    cols = np.flatnonzero(n >= _MIN_LINES)
    if cols.size < _TREND_COLS:
        return none
    r, inner_c, n_c_used = r[:, cols], inner[:, cols], n[cols]
    med, mad = _column_median_mad(r, inner_c)
    spread = _MAD_SIGMA * mad
    var = _MEDIAN_VAR * spread**2 / n_c_used
    # the smooth part across the columns is the ball's, not the sensor's.  A
    # defective (stuck, dead, hot) column is no gain: dividing by its value
    # (near 0 for a stuck column) would scale its signal by hundreds, and
    # it bends its neighbours' trend; such columns are taken out
    # one by one, the worst first, their value interpolated for the trend
    k = np.arange(med.size)
    far_all = np.zeros(med.size, dtype=bool)
    for _ in range(_MAX_DEFECTS + 1):
        base = np.where(far_all, np.interp(k, k[~far_all], med[~far_all]), med) if far_all.any() else med
        trend = _trend(base)
        ok = (trend > 0) & ~far_all
        if ok.sum() < _TREND_COLS:
            return none
        d = med[ok] / trend[ok] - 1.0
        # method of moments, robustly (a column at the ball's end or one with a
        # seam may be far off): what the columns' scatter exceeds their noise by
        dev = np.abs(d - median(d))
        scatter = _MAD_SIGMA * float(median(dev))
        # (a floor of 0.1 %: on a noise-free image neither scatter nor noise is there)
        z = dev / np.maximum(np.sqrt(scatter**2 + var[ok]), _DEFECT_FLOOR)
        worst = int(np.argmax(z))
        if z[worst] <= _DEFECT_SIGMAS or far_all.sum() == _MAX_DEFECTS:
            break
        far_all[np.flatnonzero(ok)[worst]] = True
    d_far = np.abs(med[far_all] / np.where(trend[far_all] > 0, trend[far_all], 1.0) - 1.0)
    tau2 = max(scatter**2 - float(median(var[ok])), 0.0)
    gain = np.ones(n_c)
    sigma = np.full(n_c, math.sqrt(tau2))
    if tau2 > 0:
        gain[cols[ok]] = 1.0 + d * (tau2 / (tau2 + var[ok]))
        # the measurement's posterior, and the part of the gains the smooth
        # trend takes with the ball's shading (a white gain pattern leaves
        # sum(coef^2) = 0.2 of its variance in a 15-column quadratic, which
        # the posterior alone leaves out)
        sigma[cols[ok]] = np.sqrt(tau2 * var[ok] / (tau2 + var[ok]) + tau2 * _trend_filter()[2])
    # the defective columns keep gain 1 and their whole deviation as their error
    sigma[cols[far_all]] = np.maximum(d_far, math.sqrt(tau2))
    return ColumnGains(col_start, gain, n, float(np.sqrt(tau2)), int(ok.sum()), sigma)


def flat_fielded(data: np.ndarray, background: np.ndarray, gains: ColumnGains, lines: slice, saturation_dn: float | None = None) -> np.ndarray:
    """A copy of ``data`` with the gains divided out of the ball's signal on ``lines`` of the gains' columns.

    ``background + (data - background) / gain``: the detector's per-column
    background already holds each column's gain on the background.  Pixels
    at or above ``saturation_dn`` keep their value (still saturated).
    """
    out = np.array(data, dtype=float, copy=True)
    cs = slice(gains.col_start, gains.col_start + gains.gain.size)
    raw = out[lines, cs]
    bg = background[lines, cs]
    ff = bg + (raw - bg) / gains.gain[None, :]
    if saturation_dn is not None:
        # saturated pixels stay saturated, the others stay below it
        ff = np.where(raw >= saturation_dn, raw, np.minimum(ff, np.nextafter(saturation_dn, -np.inf)))
    out[lines, cs] = ff
    return out
