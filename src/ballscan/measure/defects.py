"""Stuck sensor columns: a pixel column that does not see the ball, replaced by its neighbours.

A dead or hot column of a line-scan sensor reads one level whatever the
scene: where a ball crosses it, its pixels keep that level while both
neighbours see the ball.  The detector learns that level as the column's
background, so the column's signal on the ball is zero: the window edges of
a limb beside it are read at the column instead of the limb (several pixels
inside, changing along the passage), and a ball crossed by it may be split
in two regions.  Such a column carries no information about the ball.

:func:`stuck_columns` finds the columns whose signal stays near zero on the
lines where a neighbour sees a detected ball clearly, and whose values
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

#: Lines on which a neighbour must see the ball for a column to be judged.
MIN_LINES = 8
#: A neighbour sees the ball clearly: its signal exceeds this many of its noise sigmas.
STRONG_SIGMA = 5.0
#: A stuck column's median signal, as a share of its seeing neighbours' mean signal, is below this.
STUCK_RESPONSE = 0.25
#: A stuck column's values on those lines spread (robust sigma) by at most this many of its noise sigmas.
FLAT_SIGMA = 3.0
#: A stuck column's background level lies this many noise sigmas off the median of the two
#: columns on each side (a dead column reads the black level, a hot one a fixed bright level).
LEVEL_SIGMA = 5.0


def stuck_columns(image: LineImage, detection: Detection) -> np.ndarray:
    """Sensor columns that do not respond where their neighbours see a detected ball.

    A column is stuck when its background level lies :data:`LEVEL_SIGMA`
    noise sigmas off the median of the two columns on each side and, on at
    least :data:`MIN_LINES` lines of a region where a neighbour's signal
    exceeds :data:`STRONG_SIGMA` noise sigmas, its own signal is a median
    below :data:`STUCK_RESPONSE` of the seeing neighbours' mean while its
    values there spread by at most :data:`FLAT_SIGMA` of its noise.  A
    column off its neighbours' level never counts as a seeing neighbour.
    On the 306 images of the POV-Ray set, the shared reference scenes and
    the test data (52 with a dead or hot column, most of them away from the
    ball) this finds 16 defective columns, each at a ball's limb or inside
    it, and no other column.

    Parameters
    ----------
    image : LineImage
        The image the detection was made on (DN).
    detection : Detection
        Its detection: the regions' boxes and polarities, the per-column
        background and noise.

    Returns
    -------
    numpy.ndarray
        Column indices (int, sorted, unique); empty when none is stuck.
        Columns one beyond each region's box are judged too (a stuck
        column may end or split a ball's region).
    """
    x = image.data
    width = x.shape[1]
    bg, noise = detection.background_dn, detection.noise_dn
    level_off = np.zeros(width, dtype=bool)
    for r in detection.regions:
        # (the columns judged and their neighbours)
        span = np.arange(max(r.col_start - 2, 0), min(r.col_stop + 2, width))
        level_off[span] = _level_outliers(bg, noise, span)
    found: set[int] = set()
    for r in detection.regions:
        c0, c1 = max(r.col_start - 1, 1), min(r.col_stop + 1, width - 1)
        # only a column off its neighbours' level can be stuck: most balls have none
        candidates = c0 + np.flatnonzero(level_off[c0:c1])
        if candidates.size == 0:
            continue
        ls = slice(r.line_start, r.line_stop)
        for j in candidates:
            cs = slice(j - 1, j + 2)
            signal = r.polarity * (x[ls, cs] - background_at(detection, ls, cs))
            # a column off its neighbours' level does not vouch for a ball (a
            # hot column's signal follows the lines' drift, not the scene)
            left, right = ((signal[:, k] > STRONG_SIGMA * noise[j + k - 1]) & ~level_off[j + k - 1] for k in (0, 2))
            on = left | right
            if on.sum() < MIN_LINES:
                continue
            seen = np.where(left & right, 0.5 * (signal[:, 0] + signal[:, 2]), np.where(left, signal[:, 0], signal[:, 2]))[on]
            if np.median(signal[on, 1] / seen) >= STUCK_RESPONSE:
                continue
            raw = x[ls, j][on]
            if MAD_TO_SIGMA * np.median(np.abs(raw - np.median(raw))) <= FLAT_SIGMA * noise[j]:
                found.add(int(j))
    return np.array(sorted(found), dtype=np.intp)


def _level_outliers(bg: np.ndarray, noise: np.ndarray, cols: np.ndarray) -> np.ndarray:
    """Whether each of ``cols`` has a background level :data:`LEVEL_SIGMA` noise sigmas off the median of the two columns on each side."""
    # the two columns on each side, mirrored at the sensor's ends
    idx = np.abs(cols[:, None] + np.array([-2, -1, 1, 2])[None, :])
    idx = np.where(idx >= bg.size, 2 * (bg.size - 1) - idx, idx).clip(0, bg.size - 1)
    level = np.median(bg[idx], axis=1)
    scale = np.maximum(np.median(noise[idx], axis=1), noise[cols])
    return np.abs(bg[cols] - level) > LEVEL_SIGMA * scale


def _interpolate(values: np.ndarray, columns: np.ndarray) -> np.ndarray:
    """``values`` (..., W) with ``columns`` replaced by the linear interpolation of the nearest other columns."""
    out = np.array(values, dtype=np.float64, copy=True)
    good = np.ones(out.shape[-1], dtype=bool)
    good[columns] = False
    keep = np.flatnonzero(good)
    if keep.size == 0:
        return out
    for j in columns:
        lo, hi = keep[keep < j], keep[keep > j]
        if lo.size and hi.size:
            a, b = int(lo[-1]), int(hi[0])
            w = (j - a) / (b - a)
            out[..., j] = (1.0 - w) * out[..., a] + w * out[..., b]
        else:
            out[..., j] = out[..., int(lo[-1]) if lo.size else int(hi[0])]
    return out


def repaired_image(image: LineImage, columns: np.ndarray) -> LineImage:
    """A copy of ``image`` whose ``columns`` hold their neighbours' linear interpolation on every line."""
    return replace(image, data=_interpolate(image.data, np.asarray(columns, dtype=np.intp)))


def repaired_columns(model: ColumnModel, columns: np.ndarray) -> ColumnModel:
    """A known column model with the background and noise of ``columns`` interpolated from their neighbours'."""
    c = np.asarray(columns, dtype=np.intp)
    return ColumnModel(_interpolate(model.background_dn, c), _interpolate(model.noise_dn, c))
