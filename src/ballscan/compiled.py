"""The project's numba decorator, the conversion of a kernel's array arguments and the loops several stages' kernels share.

Every compiled loop of the package is decorated with :func:`jit` (compiled
on first use and cached on disk) and called on arrays passed through
:func:`as_arg`, so that each kernel holds one compiled signature.
:func:`pairwise_sum` (numpy's sum) and :func:`select_kth` (a median's
selection) serve the kernels of more than one stage.
"""

from __future__ import annotations

import os

import numpy as np
from numba import njit
from numba.extending import register_jitable

#: Every kernel made by :func:`jit` (inline helpers aside), by the module that defines it.
KERNELS: dict[str, list] = {}


def jit(**options):
    """``numba.njit`` cached on disk where numba finds a writable cache location, else compiled per process.

    With ``cache=True`` numba raises at decoration when it has nowhere to
    write (a read-only install without a writable home or
    ``NUMBA_CACHE_DIR``); the estimator must still import there.  The
    kernel is registered in :data:`KERNELS`, except an ``inline="always"``
    helper, which compiles into its callers and has no code of its own.
    """

    def decorate(func):
        try:
            kernel = njit(cache=True, **options)(func)
        except RuntimeError:
            kernel = njit(cache=False, **options)(func)
        if options.get("inline") != "always":
            KERNELS.setdefault(func.__module__, []).append(kernel)
        return kernel

    return decorate


def _cache_file(kernel):
    """numba's on-disk cache file of ``kernel``, or None where it is not cached."""
    cache = getattr(kernel, "_cache", None)
    return getattr(cache, "_cache_file", None)


def is_cached(kernel) -> bool | None:
    """Whether ``kernel`` has compiled code on disk for its current source (None where numba's cache cannot tell).

    Reads numba's cache index (an internal of ``numba.core.caching``, stable
    since numba 0.49), which is empty when the source changed since.
    """
    if getattr(kernel, "signatures", None):
        return True  # already compiled or loaded in this process
    try:
        return bool(_cache_file(kernel)._load_index())
    except Exception:  # a numba without this internal: unknown, not an error
        return None


def cache_dir(modules=None) -> str | None:
    """The folder that holds the kernels' disk cache: ``NUMBA_CACHE_DIR`` when set, else the ``__pycache__`` folders under the package (or the user's cache for a read-only install).

    ``modules``: the kernel modules to look at (default all); None when none is cached.
    """
    names = KERNELS if modules is None else [m for m in modules if m in KERNELS]
    paths = [getattr(getattr(k, "_cache", None), "_cache_path", None) for m in names for k in KERNELS[m]]
    paths = [str(p) for p in paths if p]
    return os.path.commonpath(paths) if paths else None


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


@jit(inline="always")
def select_kth(buf: np.ndarray, m: int, k: int):
    """The ``k``-th smallest (0-based) of ``buf[:m]``, by Hoare's selection in place: afterwards ``buf[:k] <= buf[k] <= buf[k + 1 : m]``.

    Compiled into each kernel that calls it, for ``buf``'s dtype (floats, or
    integers for the stream engine's fixed-point offsets).
    """
    lo = 0
    hi = m - 1
    while lo < hi:
        pivot = buf[(lo + hi) >> 1]
        i = lo
        j = hi
        while i <= j:
            while buf[i] < pivot:
                i += 1
            while buf[j] > pivot:
                j -= 1
            if i <= j:
                t = buf[i]
                buf[i] = buf[j]
                buf[j] = t
                i += 1
                j -= 1
        if k <= j:
            hi = j
        elif k >= i:
            lo = i
        else:
            break
    return buf[k]
