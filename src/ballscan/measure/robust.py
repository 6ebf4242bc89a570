"""Robust statistics shared by the measuring, solving and streaming stages.

The functions return exactly what their numpy counterparts return (value and
dtype, bit for bit), at a fraction of the cost on the sizes met per ball:
``np.median`` partitions at both middle ranks at once, and numpy's partition
at several ranks is several times slower than at one.
"""

from __future__ import annotations

import numpy as np

__all__ = ["MAD_TO_SIGMA", "median", "weighted_median"]

#: Median absolute deviation to the standard deviation of normal noise,
#: ``1 / Phi^-1(3/4)``.
MAD_TO_SIGMA = 1.482602218505602


def median(a: np.ndarray) -> np.floating:
    """``np.median`` of all of ``a``, by one selection.

    The same value and type as ``np.median``: the middle order statistic, or
    the mean of the two middle ones, of the same dtype (NaN if any value is
    NaN).  It partitions at the upper middle rank only and takes the lower
    middle value as the largest value below it: one partition instead of
    ``np.median``'s partition at two ranks.

    Parameters
    ----------
    a : array_like
        Any shape; integers and booleans are averaged in float64, as by
        ``np.median``.

    Returns
    -------
    numpy.floating
        The median, of ``a``'s float dtype (float64 for integers).

    Raises
    ------
    ValueError
        If ``a`` is empty.
    """
    a = np.asarray(a)
    if a.size == 0:
        raise ValueError("median: empty array")
    if a.dtype.kind in "biu":
        a = a.astype(np.float64)  # as np.median: integers average in float64
    a = a.ravel()
    if a.dtype.kind == "f" and np.isnan(a).any():
        return a.dtype.type(np.nan)
    h = a.size // 2
    p = np.partition(a, h)
    hi = p[h]
    if a.size % 2:
        return hi
    # numpy scalars of a's dtype: the mean of the two in that precision, as np.median
    return (p[:h].max() + hi) / 2


def weighted_median(values: np.ndarray, counts: np.ndarray) -> float:
    """``np.median`` of ``values`` repeated ``counts`` times, without repeating them.

    Parameters
    ----------
    values : numpy.ndarray
        1-D.
    counts : numpy.ndarray
        1-D integer counts of ``values``' entries, ``>= 0``, summing to more
        than 0.

    Returns
    -------
    float
        The middle value, or the mean of the two middle ones, of the
        repeated values.
    """
    order = np.argsort(values, kind="stable")
    v, c = values[order], np.cumsum(counts[order])
    m = int(c[-1])
    lo = v[np.searchsorted(c, (m - 1) // 2, side="right")]
    hi = v[np.searchsorted(c, m // 2, side="right")]
    return float(lo) if m % 2 else float((lo + hi) / 2.0)
