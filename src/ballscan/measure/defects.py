"""Stuck sensor columns: a pixel column that does not see the ball, replaced by its neighbours.

A dead or hot column of a line-scan sensor reads one level whatever the
scene: where a ball crosses it, its pixels keep that level while both
neighbours see the ball.  The detector learns that level as the column's
background, so the column's signal on the ball is zero: the window edges of
a limb beside it are read at the column instead of the limb (several pixels
inside, changing along the passage), and a ball crossed by it may be split
in two regions.  Such a column carries no information about the ball.

:func:`stuck_columns` finds the columns whose signal stays near zero on the
lines where both neighbours see a detected ball clearly, and whose values
there are as flat as their own noise (a stuck column does not vary; a dark
seam or stitch that happens to follow one column over a few lines does),
and whose background level is off their neighbours';
:func:`repaired_image` and :func:`repaired_columns` put the neighbours'
linear interpolation in their place, for the image and for a known column
model, before the balls are detected and measured again.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from .detection import ColumnModel, Detection, background_at
from .images import LineImage
from .robust import MAD_TO_SIGMA

__all__ = ["MIN_LINES", "STRONG_SIGMA", "STUCK_RESPONSE", "FLAT_SIGMA", "LEVEL_SIGMA", "stuck_columns", "repaired_image", "repaired_columns"]

#: Lines on which both neighbours must see the ball for a column to be judged.
MIN_LINES = 8
#: A neighbour sees the ball clearly: its signal exceeds this many of its noise sigmas.
STRONG_SIGMA = 5.0
#: A stuck column's signal over its neighbours' mean, line by line, has a median below this.
STUCK_RESPONSE = 0.25
#: A stuck column's values on those lines spread (robust sigma) by at most this many of its noise sigmas.
FLAT_SIGMA = 3.0
#: A stuck column's background level lies this many noise sigmas off the median of the three
#: columns on each side (a dead column reads the black level, a hot one a fixed bright level).
LEVEL_SIGMA = 5.0


def stuck_columns(image: LineImage, detection: Detection) -> np.ndarray:
    """Sensor columns that do not respond where both their neighbours see a detected ball.

    A column is stuck when its background level lies :data:`LEVEL_SIGMA`
    noise sigmas off the median of the three columns on each side and, on
    at least :data:`MIN_LINES` lines of a region where both neighbours'
    signals exceed :data:`STRONG_SIGMA` noise sigmas (one neighbour at the
    sensor's ends), the median of its signal over their mean, line by line,
    is below :data:`STUCK_RESPONSE` while its values there spread by at
    most :data:`FLAT_SIGMA` of its noise.  The neighbours are the nearest
    columns on each side (within three) that are on their own neighbours'
    level: two stuck columns side by side are judged against the healthy
    ones beyond them.  Requiring the ball on both
    sides keeps a backdrop's own vertical line or step beside the ball's
    outline from being taken for a stuck column (it too is off level, flat
    and without the ball's signal); a stuck column that is the limb's
    outermost pixel is missed.

    Parameters
    ----------
    image : LineImage
        The image the detection is made on (DN).
    detection : Detection
        Its detection: the regions' boxes and polarities, the per-column
        background and noise.

    Returns
    -------
    numpy.ndarray
        Column indices (int, sorted, unique); empty when none is stuck.
        Columns one beyond each region's box are judged too (a stuck
        column may split a ball's region).
    """
    x = image.data
    width = x.shape[1]
    bg, noise = detection.background_dn, detection.noise_dn
    level_off = np.zeros(width, dtype=bool)
    found: set[int] = set()
    for r in detection.regions:
        c0, c1 = max(r.col_start - 1, 0), min(r.col_stop + 1, width)
        # the columns judged and the neighbours they may be judged against
        span = np.arange(max(c0 - 3, 0), min(c1 + 3, width))
        level_off[span] = _level_outliers(bg, noise, span)
        # only a column off its neighbours' level can be stuck: most balls have none
        candidates = c0 + np.flatnonzero(level_off[c0:c1])
        ls = slice(r.line_start, r.line_stop)
        for j in candidates:
            if _stuck(x[ls], detection, r.polarity, int(j), level_off, ls):
                found.add(int(j))
    return np.array(sorted(found), dtype=np.intp)


def _stuck(x: np.ndarray, detection: Detection, polarity: int, j: int, level_off: np.ndarray, ls: slice) -> bool:
    """Whether column ``j`` stays flat without the ball's signal where its neighbours (both, where it has two) see it; ``x`` the region's lines."""
    width, noise = x.shape[1], detection.noise_dn
    # the nearest column on each side that is on its neighbours' level (a
    # column off it does not vouch for a ball: a hot column's signal follows
    # the lines' drift, not the scene), within three
    sides = []
    for step in (-1, 1):
        k = j + step
        while 0 <= k < width and abs(k - j) <= 3 and level_off[k]:
            k += step
        if 0 <= k < width and abs(k - j) <= 3:
            sides.append(k)
        elif 0 <= j + step < width:
            return False  # a neighbour exists but none on level near it
    cols = [j, *sides]
    signal = polarity * (x[:, cols] - background_at(detection, ls, np.array(cols)))
    seeing = [signal[:, i + 1] > STRONG_SIGMA * noise[k] for i, k in enumerate(sides)]
    on = np.logical_and.reduce(seeing)
    if on.sum() < MIN_LINES:
        return False
    seen = np.mean(signal[on][:, 1:], axis=1)
    if np.median(signal[on, 0] / seen) >= STUCK_RESPONSE:
        return False
    raw = x[on, j]
    return bool(MAD_TO_SIGMA * np.median(np.abs(raw - np.median(raw))) <= FLAT_SIGMA * noise[j])


def _level_outliers(bg: np.ndarray, noise: np.ndarray, cols: np.ndarray) -> np.ndarray:
    """Whether each of ``cols`` has a background level :data:`LEVEL_SIGMA` noise sigmas off the median of the three columns on each side.

    Three a side: two stuck columns side by side leave the median to four
    healthy ones.  At the sensor's ends the columns that exist are used.
    """
    idx = cols[:, None] + np.array([-3, -2, -1, 1, 2, 3])[None, :]
    valid = (idx >= 0) & (idx < bg.size)
    idx = idx.clip(0, bg.size - 1)
    level, scale = np.median(bg[idx], axis=1), np.median(noise[idx], axis=1)
    for i in np.flatnonzero(~valid.all(axis=1)):  # (the sensor's first and last three columns)
        near = idx[i, valid[i]]
        level[i], scale[i] = np.median(bg[near]), np.median(noise[near])
    return np.abs(bg[cols] - level) > LEVEL_SIGMA * np.maximum(scale, noise[cols])


def _interpolate(values: np.ndarray, columns: np.ndarray) -> np.ndarray:
    """``values`` (..., W) with ``columns`` replaced by the linear interpolation of the nearest other columns (the nearest one beyond the last)."""
    out = np.array(values, dtype=np.float64, copy=True)
    keep = np.setdiff1d(np.arange(out.shape[-1]), columns)
    if keep.size == 0 or len(columns) == 0:
        return out
    pos = np.searchsorted(keep, columns)
    a, b = keep[np.maximum(pos - 1, 0)], keep[np.minimum(pos, keep.size - 1)]
    w = np.where(b > a, (columns - a) / np.maximum(b - a, 1), 0.0)
    out[..., columns] = (1.0 - w) * out[..., a] + w * out[..., b]
    return out


def repaired_image(image: LineImage, columns: np.ndarray) -> LineImage:
    """A copy of ``image`` whose ``columns`` hold their neighbours' linear interpolation on every line."""
    return replace(image, data=_interpolate(image.data, np.asarray(columns, dtype=np.intp)))


def repaired_columns(model: ColumnModel, columns: np.ndarray) -> ColumnModel:
    """A known column model with the background and noise of ``columns`` interpolated from their neighbours'."""
    c = np.asarray(columns, dtype=np.intp)
    return ColumnModel(_interpolate(model.background_dn, c), _interpolate(model.noise_dn, c))
