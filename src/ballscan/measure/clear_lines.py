"""The scan lines that show the backdrop alone, and the background level they give each column.

A line-scan camera sees the same backdrop on every line, times the lamp's
level on that line (drift, flicker). A line that no ball crosses therefore
matches every other such line pixel by pixel after one scale factor (or,
on a backdrop near zero, one offset), while a line a ball crosses differs
from them wherever the ball is. The lines without a ball are found as the
largest set of lines that match one line (the line that matches the most
others): this holds where a ball covers most of a column's lines or most
of a line's pixels, where a per-column or per-line median reads the ball.

Their per-column median is the backdrop's profile, with its gradient
across the sensor, its dead, hot and gain-varied columns
(:func:`clear_line_levels`); :func:`line_levels` then finds each line's
scale (or offset) as the one that puts the most pixels of the line on
that profile, within the range of scales the ball-free lines show.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass

import numpy as np

from ..compiled import as_arg
from ._detection_kernels import on_first, pair_offs, scale_counts
from .robust import MAD_TO_SIGMA

__all__ = ["ClearLines", "clear_line_levels", "column_noise", "line_levels"]

#: Most lines compared pairwise (their matches cost the square of this count).
_SAMPLE_LINES = 64
#: A pixel differs from the other line where the difference exceeds this many sigmas.
_MATCH_SIGMA = 5.0
#: Most pairs of consecutive lines the columns' noise is measured on.
_NOISE_PAIRS = 128
#: Fewest lines without a ball for their profile to be used.
_MIN_CLEAR = 3


@dataclass(frozen=True, eq=False)
class ClearLines:
    """The ball-free lines among the compared ones and the backdrop's profile from them.

    Attributes
    ----------
    lines : numpy.ndarray
        int64, the indices (into the image's lines) of the ball-free lines found.
    level_dn : numpy.ndarray
        float64, shape ``(W,)``: per-column background (DN) at the image's
        reference level (a line scale of 1, or a line offset of 0).
    scale_range : tuple of float
        Smallest and largest line scale (gain model, relative to the
        reference level) or line offset (DN, offset model) of those lines.
    """

    lines: np.ndarray
    level_dn: np.ndarray
    scale_range: tuple[float, float]


def column_noise(x: np.ndarray, level: np.ndarray, ref: float, use_gain: bool) -> np.ndarray:
    """Per-column noise sigma (DN) from the differences of consecutive lines, each line brought to the reference level.

    Parameters
    ----------
    x : numpy.ndarray
        float, shape ``(n, W)``, ``n >= 2``: the image's lines (DN).
    level : numpy.ndarray
        float, shape ``(n,)``: each line's level (its median, DN).
    ref : float
        The reference level (DN).
    use_gain : bool
        Lines are scaled by ``ref / level`` (lamp drift, flicker), else
        shifted by ``ref - level``.

    Returns
    -------
    numpy.ndarray
        float64, shape ``(W,)``: ``MAD_TO_SIGMA * MAD / sqrt(2)`` of each
        column's differences. A ball changes a column's differences only on
        the few lines where its edges cross it, and a flickering lamp not at
        all once the lines are levelled, so neither widens it.
    """
    # at most _NOISE_PAIRS pairs of consecutive lines: the MAD to a few per cent
    i = np.unique(np.linspace(0, x.shape[0] - 2, min(x.shape[0] - 1, _NOISE_PAIRS)).round().astype(np.int64))
    a = _levelled(np.asarray(x[i], dtype=np.float64), level[i], ref, use_gain)
    b = _levelled(np.asarray(x[i + 1], dtype=np.float64), level[i + 1], ref, use_gain)
    d = b - a
    med = np.median(d, axis=0)
    return MAD_TO_SIGMA * np.median(np.abs(d - med), axis=0) / np.sqrt(2.0)


def _levelled(x: np.ndarray, level: np.ndarray, ref: float, use_gain: bool) -> np.ndarray:
    """The lines brought to the reference level: ``x * ref / level`` (gain model) or ``x + ref - level``."""
    if use_gain:
        return x * (ref / np.where(level > 0, level, ref))[:, None]
    return x + (ref - level)[:, None]


def clear_line_levels(
    x: np.ndarray, level: np.ndarray, ref: float, noise_dn: np.ndarray, use_gain: bool, saturation_dn: float = np.inf
) -> ClearLines | None:
    """The ball-free lines of an image and the per-column background they give (see the module docstring).

    Parameters
    ----------
    x : numpy.ndarray
        float, shape ``(n, W)``: the image's lines (DN).
    level : numpy.ndarray
        float, shape ``(n,)``: each line's median (DN).
    ref : float
        The reference level (DN): the median of ``level``.
    noise_dn : numpy.ndarray
        float, shape ``(W,)``: per-column noise sigma (DN, floored > 0).
    use_gain : bool
        Drift model: a scale per line (True) or an offset (False).
    saturation_dn : float, optional
        Level (DN) at or above which pixels are clipped: they neither tell
        lines apart nor enter the profile (a bright backdrop clips on a
        flickering lamp's brightest lines).

    Returns
    -------
    ClearLines or None
        None where fewer than 3 compared lines match the best line (no
        backdrop seen alone often enough to trust its profile).
    """
    n, w = x.shape
    idx = np.unique(np.linspace(0, n - 1, min(n, _SAMPLE_LINES)).round().astype(np.int64))
    raw = np.asarray(x[idx], dtype=np.float64)
    clipped = raw >= saturation_dn
    full = _levelled(raw, level[idx], ref, use_gain)
    # a few hundred columns tell a ball-free line from a crossed one
    step = max(1, w // 256)
    xs = full[:, ::step]
    cl = clipped[:, ::step]
    tol = _MATCH_SIGMA * np.sqrt(2.0) * np.asarray(noise_dn, dtype=np.float64)[::step]
    allowed = 1  # a noise spike; two pixels off are a ball's narrowest chord
    # the clip level of each compared line, levelled like its values
    clip_at = _levelled(np.full((idx.size, 1), float(saturation_dn)), level[idx], ref, use_gain)[:, 0]
    offs = _pair_offs(xs, cl, clip_at, tol, use_gain)
    match = offs.sum(axis=2) <= allowed
    match &= match.T
    best = _backdrop_line(match, offs, allowed)
    sel = np.flatnonzero(match[best])
    if sel.size < _MIN_CLEAR:
        return None
    rows = np.where(clipped[sel], np.nan, full[sel])
    # each clear line's own scale against the best one, so that the profile
    # is their median at one level
    if use_gain:
        with np.errstate(divide="ignore", invalid="ignore"):
            s = _nanmedian(np.where(full[best] > 0, rows / full[best][None, :], np.nan), axis=1)
        s = np.where(np.isfinite(s) & (s > 0), s, 1.0)
        profile = _nanmedian(rows / s[:, None], axis=0)
        scale = s * level[idx[sel]] / ref
    else:
        s = _nanmedian(rows - full[best][None, :], axis=1)
        s = np.where(np.isfinite(s), s, 0.0)
        profile = _nanmedian(rows - s[:, None], axis=0)
        scale = s + level[idx[sel]] - ref
    # a column clipped on every clear line: at least its clipped level
    profile = np.where(np.isfinite(profile), profile, np.median(full[sel], axis=0))
    # the profile at the reference level: the clear lines' median scale is 1 (offset 0)
    mid = float(np.median(scale))
    if use_gain:
        profile = profile * mid
        scale = scale / mid
    else:
        profile = profile + mid
        scale = scale - mid
    return ClearLines(lines=idx[sel], level_dn=profile, scale_range=(float(scale.min()), float(scale.max())))


def _pair_offs(xs: np.ndarray, cl: np.ndarray, clip_at: np.ndarray, tol: np.ndarray, use_gain: bool) -> np.ndarray:
    """``offs[i, k, j]``: pixel ``j`` of line ``i`` differs from line ``k``'s after the one factor (offset) that fits them best.

    ``xs`` are the levelled lines, ``cl`` their clipped pixels, ``clip_at``
    each line's levelled clip level and ``tol`` the per-column tolerance
    (DN). A clipped pixel differs only where the other line puts it well
    below the clip.
    """
    # compiled (_detection_kernels.pair_offs): the pairs' factors from some
    # 64 columns (well within the tolerance), then each pixel against them
    stride = max(1, xs.shape[1] // 64)
    return pair_offs(as_arg(xs), as_arg(cl, np.bool_), as_arg(clip_at), as_arg(tol), use_gain, stride, bool(cl.any()))


def _nanmedian(a: np.ndarray, axis: int) -> np.ndarray:
    """``numpy.nanmedian`` along ``axis``; NaN where a row (column) holds no value, without a warning."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        return np.nanmedian(a, axis=axis)


def _backdrop_line(match: np.ndarray, offs: np.ndarray, allowed: int, candidates: int = 3) -> int:
    """The compared line that shows the backdrop, among the best-matched lines of the largest groups of matching lines.

    Lines that hold a ball's wide middle can match one another as well as
    the ball-free lines do (a dark, even ball on a short image), so the
    largest group alone does not say which is the backdrop. The choice, in
    this order: a line that the image's first and last lines both match
    (where no ball is cut by the first or last line, the backdrop shows at
    both ends, a ball's line at neither);
    then the largest group, unless another one at least half its size
    explains the lines clearly better by one run of differing pixels each
    (against the backdrop every line differs where a ball covers it, one
    run per ball; against a ball's line, a line crossed by a narrower chord
    differs on both sides of that chord).
    """
    free = np.ones(match.shape[0], dtype=bool)
    picks: list[int] = []
    sizes: list[int] = []
    for _ in range(candidates):
        if not free.any():
            break
        counts = np.where(free, (match & free[None, :]).sum(axis=1), -1)
        b = int(np.argmax(counts))
        if picks and counts[b] < _MIN_CLEAR:
            break
        picks.append(b)
        sizes.append(int(counts[b]))
        free &= ~match[b]
        free[b] = False
    if len(picks) == 1:
        return picks[0]
    ends = [int(offs[b][0].sum() > allowed) + int(offs[b][-1].sum() > allowed) for b in picks]
    keep = [k for k in range(len(picks)) if ends[k] == 0] or list(range(len(picks)))
    multi = {}
    for k in keep:
        d = offs[picks[k]]
        # gaps of up to two pixels (a seam, a limb at the backdrop's level) close
        g = d.copy()
        g[:, 1:] |= d[:, :-1]
        g[:, :-1] |= d[:, 1:]
        runs = (g[:, 1:] & ~g[:, :-1]).sum(axis=1) + g[:, 0]
        multi[k] = int((runs >= 2).sum())
    first = keep[0]
    best = min(keep, key=lambda k: multi[k])
    if 2 * multi[best] + 3 <= multi[first] and 2 * sizes[best] >= sizes[first]:
        return picks[best]
    return picks[first]


def line_levels(
    x: np.ndarray,
    profile_dn: np.ndarray,
    noise_dn: np.ndarray,
    first: np.ndarray,
    scale_range: tuple[float, float],
    use_gain: bool,
    k_sigma: float = 3.0,
    saturation_dn: float = np.inf,
) -> np.ndarray:
    """Each line's scale (offset) on ``profile_dn``: the one that puts the most of its pixels within ``k_sigma`` noise of it.

    Parameters
    ----------
    x : numpy.ndarray
        float, shape ``(n, W)``: the image's lines (DN).
    profile_dn : numpy.ndarray
        float, shape ``(W,)``: the backdrop's per-column level (DN) at scale 1 (offset 0).
    noise_dn : numpy.ndarray
        float, shape ``(W,)``: per-column noise sigma (DN, > 0).
    first : numpy.ndarray
        float, shape ``(n,)``: a first scale (offset) per line (from the lines'
        medians); kept where it lies in the searched range and at least
        half the line's pixels lie on it.
    scale_range : tuple of float
        The scales (offsets) the ball-free lines show: the search covers
        this range widened by a quarter of its width and 4 relative noise
        sigmas on each side.
    use_gain : bool
        Scale (True) or offset (False) model.
    k_sigma : float, optional
        Half-width of the window, noise sigmas.
    saturation_dn : float, optional
        Level (DN) at or above which pixels are clipped: a clipped pixel
        lies on any scale whose background reaches the clip.

    Returns
    -------
    numpy.ndarray
        float64, shape ``(n,)``: the scale (offset) per line. A ball can
        cover most of a line's pixels, but its pixels spread over its
        shading while the backdrop's lie within the noise of one scale.
    """
    half = k_sigma * np.asarray(noise_dn, dtype=np.float64)
    unit = np.maximum(np.abs(profile_dn), 1e-12) if use_gain else np.ones_like(profile_dn)

    out = np.asarray(first, dtype=np.float64).copy()
    lo, hi = scale_range
    rel = float(np.median(noise_dn / unit))
    pad = 0.25 * (hi - lo) + 4.0 * rel
    outside = (out < lo - pad) | (out > hi + pad)
    bad = np.flatnonzero(outside | (_on_first(x, out, profile_dn, half, use_gain, saturation_dn) < 0.5 * x.shape[1]))
    if bad.size == 0:
        return out
    step = max(0.5 * rel, 1e-9)
    grid = np.arange(lo - pad, hi + pad + step, step)
    for a in range(0, bad.size, 64):
        b = bad[a : a + 64]
        counts = scale_counts(as_arg(x[b]), grid, as_arg(profile_dn), as_arg(half), use_gain, float(saturation_dn))
        top = counts.max(axis=1)
        # among the best scales, the run of them nearest the first, its middle
        tied = counts == top[:, None]
        near = np.argmin(np.where(tied, np.abs(grid[None, :] - out[b][:, None]), np.inf), axis=1)
        for q, k in enumerate(near):
            lo_k, hi_k = k, k
            while lo_k > 0 and tied[q, lo_k - 1]:
                lo_k -= 1
            while hi_k < grid.size - 1 and tied[q, hi_k + 1]:
                hi_k += 1
            out[b[q]] = 0.5 * (grid[lo_k] + grid[hi_k])
    return out


def _on_first(x: np.ndarray, first: np.ndarray, profile_dn: np.ndarray, half: np.ndarray, use_gain: bool, saturation_dn: float) -> np.ndarray:
    """Pixels of each line within ``half`` of its first scale's (offset's) background, or clipped where that background reaches the clip."""
    # compiled (_detection_kernels.on_first): one pass over the image, in its float32
    return on_first(as_arg(x, np.float32), as_arg(first), as_arg(profile_dn), as_arg(half), use_gain, float(saturation_dn))
