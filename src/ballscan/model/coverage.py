"""The coverage of a line's pixels by its chord samples: one histogram over a unit pixel grid.

The pixel model (:mod:`ballscan.model._forward_kernels`) and the limb
profile (:mod:`ballscan.measure._shading_kernels`) both integrate a line's
chord samples over its pixels; these compiled helpers are inlined into
their loops.  numba's disk cache of a kernel is keyed to its own source
file: after an edit here, delete the cached ``*.nbi``/``*.nbc`` files
(``__pycache__``) so that the callers compile again.
"""

from __future__ import annotations

import math

import numpy as np

from ..compiled import jit


@jit(inline="always")
def ramp_histogram(lo: np.ndarray, hi: np.ndarray, w: np.ndarray, a0: float, span: int, hw: np.ndarray, hwf: np.ndarray) -> bool:
    """One line's chord samples as a histogram over a unit grid of ``span`` pixels from ``a0`` (pixels).

    The overlap of ``[lo, hi]`` with pixel ``k`` (``[a0 + k, a0 + k + 1]``)
    is ``ramp(hi - a) - ramp(lo - a)``, ``ramp = clip(., 0, 1)``; the sum
    of the ramps over the samples is, for all the grid's pixels at once, a
    histogram of the samples' ends by pixel (``hw``: weights, ``hwf``:
    weights times the fractional position) and its cumulative sum.  On
    return pixel ``k``'s coverage is ``hw[k + 2] + hwf[k + 1]`` (``hw``
    holds the sums over the bins from each bin up).  An infinite end lies
    beyond the grid; ``hi < lo`` covers nothing.  Returns False (the line's
    coverage undefined) where a sample is NaN.
    """
    hw[:] = 0.0
    hwf[:] = 0.0
    for j in range(lo.shape[0]):
        lj = lo[j]
        hj = hi[j]
        wj = w[j]
        if lj != lj or hj != hj or wj != wj:
            return False
        if hj < lj:
            hj = lj
        for side in range(2):
            x = hj if side == 0 else lj
            sw = wj if side == 0 else -wj
            t = x - a0
            if t >= span:
                # beyond the grid: every pixel's ramp at 1
                hw[span + 1] += sw
            elif t >= -1.0:
                b = math.floor(t)
                bi = int(b) + 1
                hw[bi] += sw
                hwf[bi] += sw * (t - b)
            # else before the grid: no pixel's ramp
    for b in range(span, -1, -1):
        hw[b] += hw[b + 1]
    return True


@jit(inline="always")
def grid_coverage(hw: np.ndarray, hwf: np.ndarray, k: int) -> float:
    """Pixel ``k``'s coverage from :func:`ramp_histogram` (exactly 0 where the two ramps of every sample cancel)."""
    cov = hw[k + 2] + hwf[k + 1]
    return 0.0 if abs(cov) < 1e-14 else cov
