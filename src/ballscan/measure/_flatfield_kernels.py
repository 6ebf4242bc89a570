"""Compiled loops of the column gains: the masked medians of :func:`ballscan.measure.flatfield.column_gains`.

The column gains take three medians of the masked pixels of a ball's box:
each line's, each column's and each column's absolute deviation from it.
numpy's sort of the box (with inf where unmasked) stays; the middle ranks
are picked here (as numpy that is the mask's counts and two gathers, small
calls whose fixed cost dominates), and the deviations' median is merged
from the same sorted columns instead of a second sort.
"""

from __future__ import annotations

import math

import numpy as np

from ..compiled import jit


@jit()
def sorted_medians(v: np.ndarray, mask: np.ndarray, axis: int) -> np.ndarray:
    """Medians of the masked values from the sorted box of :func:`ballscan.measure.flatfield._masked_median`.

    ``v`` is ``where(mask, values, inf)`` sorted along ``axis`` (0 or 1) of
    a 2-D array: along it each line (or column) of ``n`` masked values has
    its median at ranks ``(n - 1) // 2`` and ``n // 2``, ``0.5 * (lo +
    hi)``; NaN where ``n`` is 0.
    """
    n_a, n_b = v.shape
    n_out = n_b if axis == 0 else n_a
    n_along = n_a if axis == 0 else n_b
    out = np.empty(n_out)
    for o in range(n_out):
        n = 0
        for i in range(n_along):
            if (mask[i, o] if axis == 0 else mask[o, i]):
                n += 1
        if n == 0:
            out[o] = np.nan
            continue
        lo = (n - 1) // 2
        hi = n // 2
        if axis == 0:
            out[o] = 0.5 * (v[lo, o] + v[hi, o])
        else:
            out[o] = 0.5 * (v[o, lo] + v[o, hi])
    return out


@jit()
def median_deviations(v: np.ndarray, mask: np.ndarray):
    """Each row's median of the masked values and their median absolute deviation from it (:func:`ballscan.measure.flatfield._column_median_mad`).

    ``v`` is ``where(mask, values, inf)`` sorted along its rows (the box's
    columns, transposed); the median as :func:`sorted_medians`.  Where a
    row's first and ``n``-th sorted values are finite they are its ``n``
    masked values, and the deviations ``|x - med|`` in ascending order are
    those below the median walked down (``med - x``, the same value:
    rounding is symmetric) merged with those above walked up: their middle
    ranks are the deviations' median, ``0.5 * (lo + hi)``, without a second
    sort.

    Returns
    -------
    med, mad : ndarray (n_rows,)
        NaN where a row has no masked value; ``mad`` also NaN where not
        measured so (see ``exact``).
    exact : bool
        False when a row's masked values are not all finite (its deviations
        must be sorted as they are).
    """
    n_rows, n_along = v.shape
    med = np.empty(n_rows)
    mad = np.empty(n_rows)
    exact = True
    for o in range(n_rows):
        x = v[o]
        n = 0
        for i in range(n_along):
            if mask[o, i]:
                n += 1
        if n == 0:
            med[o] = np.nan
            mad[o] = np.nan
            continue
        lo = (n - 1) // 2
        hi = n // 2
        m = 0.5 * (x[lo] + x[hi])
        med[o] = m
        if not (math.isfinite(x[0]) and math.isfinite(x[n - 1])):
            exact = False
            mad[o] = np.nan
            continue
        below = 0
        while below < n and x[below] <= m:
            below += 1
        i = below - 1
        j = below
        d_lo = 0.0
        d_hi = 0.0
        for rank in range(hi + 1):
            if j >= n or (i >= 0 and m - x[i] <= x[j] - m):
                d = m - x[i]
                i -= 1
            else:
                d = x[j] - m
                j += 1
            if rank == lo:
                d_lo = d
            if rank == hi:
                d_hi = d
        mad[o] = 0.5 * (d_lo + d_hi)
    return med, mad, exact


def warm_up() -> None:
    """Load (or compile) this module's kernels now, on tiny inputs (see :func:`ballscan.pipeline.warmup.warm_up`)."""
    sorted_medians(np.zeros((1, 1)), np.ones((1, 1), dtype=np.bool_), 0)
    median_deviations(np.zeros((1, 1)), np.ones((1, 1), dtype=np.bool_))
