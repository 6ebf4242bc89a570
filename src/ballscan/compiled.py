"""The project's numba decorator and the conversion of a kernel's array arguments.

Every compiled loop of the package is decorated with :func:`jit` (compiled
on first use and cached on disk) and called on arrays passed through
:func:`as_arg`, so that each kernel holds one compiled signature.
"""

from __future__ import annotations

import numpy as np
from numba import njit
from numba.extending import register_jitable


def jit(**options):
    """``numba.njit`` cached on disk where numba finds a writable cache location, else compiled per process.

    With ``cache=True`` numba raises at decoration when it has nowhere to
    write (a read-only install without a writable home or
    ``NUMBA_CACHE_DIR``); the estimator must still import there.
    """

    def decorate(func):
        try:
            return njit(cache=True, **options)(func)
        except RuntimeError:
            return njit(cache=False, **options)(func)

    return decorate


def as_arg(a, dtype=np.float64) -> np.ndarray:
    """``a`` as a C-contiguous, writeable array of ``dtype`` (a copy only where it is not one).

    Every kernel has one compiled signature, for such arrays; a read-only
    (broadcast) or strided argument would compile another on first sight.
    ``np.require`` does the same at several times the cost (a kernel's
    arguments are converted some fifty times per ball).
    """
    if isinstance(a, np.ndarray) and a.dtype == dtype and a.flags.c_contiguous and a.flags.writeable:
        return a
    return np.array(a, dtype=dtype, order="C")


def jitable(func):
    """``func`` unchanged for Python callers, and compiled inline into any kernel that calls it.

    The formulas the numpy code and the kernels share (the lens model,
    :mod:`ballscan.geometry.lens`) are written once as plain functions on
    floats and arrays; a kernel calling one compiles the same body into its
    own loop (``numba.extending.register_jitable`` with ``inline="always"``),
    which composes: a shared function may call another.  numba's disk cache
    of a kernel is keyed to the kernel's own source file only: after an
    edit of a shared function, delete the cached ``*.nbi``/``*.nbc`` files
    (``__pycache__``) so that its callers compile again.
    """
    return register_jitable(inline="always")(func)


@jit()
def pairwise_sum(a: np.ndarray) -> float:
    """``np.sum`` of a contiguous float64 array: numpy's pairwise summation (blocks of 128 in eight lanes)."""
    n = a.shape[0]
    if n < 8:
        res = 0.0
        for i in range(n):
            res += a[i]
        return res
    if n <= 128:
        r0, r1, r2, r3, r4, r5, r6, r7 = a[0], a[1], a[2], a[3], a[4], a[5], a[6], a[7]
        m = n - n % 8
        for i in range(8, m, 8):
            r0 += a[i]
            r1 += a[i + 1]
            r2 += a[i + 2]
            r3 += a[i + 3]
            r4 += a[i + 4]
            r5 += a[i + 5]
            r6 += a[i + 6]
            r7 += a[i + 7]
        res = ((r0 + r1) + (r2 + r3)) + ((r4 + r5) + (r6 + r7))
        for i in range(m, n):
            res += a[i]
        return res
    n2 = n // 2
    n2 -= n2 % 8
    return pairwise_sum(a[:n2]) + pairwise_sum(a[n2:])
