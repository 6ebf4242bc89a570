"""The camera's radial lens distortion and its inverse (Eq. (2), geometry.md).

A normalised sensor coordinate ``n = y / z`` is seen at the distorted
coordinate ``n_d = n (1 + k1 n^2 + k2 n^4)``, the pixel
``u = principal + focal * n_d``.  The formulas are written here once, as
plain functions on floats and numpy arrays alike: the camera
(:class:`ballscan.geometry.camera.LineScanCamera`) calls them on arrays,
and the compiled kernels call them on floats inside their loops (each
function is compiled inline into the kernel that calls it, see
:func:`ballscan.compiled.jitable`).  The kernels' inverse of one pixel
(:func:`normalised`, a Newton loop) is compiled itself, inline into its
callers: numba's inlining of a plain function holding a loop trips its
SSA checks.  Arguments come in one order: the
coordinate, then ``focal_px, principal_px``, then ``k1, k2``.
"""

from __future__ import annotations

import numpy as np

from ..compiled import jit, jitable


@jitable
def distorted(n, k1, k2):
    """Distorted normalised coordinate ``n_d = n (1 + k1 n^2 + k2 n^4)`` (dimensionless), Eq. (2).

    Evaluated as ``n (1 + n^2 (k1 + k2 n^2))`` on floats and arrays alike,
    so that the camera and the kernels round alike.
    """
    n2 = n * n
    return n * (1.0 + n2 * (k1 + k2 * n2))


@jitable
def distortion_slope(n, k1, k2):
    """``d n_d / d n = 1 + 3 k1 n^2 + 5 k2 n^4`` of :func:`distorted` (dimensionless)."""
    n2 = n * n
    return 1.0 + n2 * (3.0 * k1 + 5.0 * k2 * n2)


@jitable
def newton_step(n, n_d, k1, k2):
    """One Newton step's correction of ``n`` towards the undistorted coordinate of ``n_d`` (subtract it from ``n``)."""
    return (distorted(n, k1, k2) - n_d) / distortion_slope(n, k1, k2)


@jitable
def project(n, focal_px, principal_px, k1, k2):
    """Pixel ``u = principal + focal * n_d`` of the undistorted normalised coordinate ``n`` (pixels), Eq. (2)."""
    if k1 == 0.0 and k2 == 0.0:
        return principal_px + focal_px * n
    return principal_px + focal_px * distorted(n, k1, k2)


def undistorted(n_d: np.ndarray, k1: float, k2: float, tol: float) -> tuple[np.ndarray, bool]:
    """Undistorted coordinates of the array ``n_d`` by Newton's method, and whether all converged.

    The steps go on until every element's step is below ``tol * 1e-3``
    (at most 50); converged where every residual ``|distorted(n) - n_d|``
    is within ``tol`` (normalised units: a tolerance in pixels over the
    focal length).  A coordinate beyond the distortion's monotonic range
    does not converge.
    """
    n_d = np.asarray(n_d, dtype=float)
    if k1 == 0.0 and k2 == 0.0:
        return n_d.copy(), True
    n = n_d.copy()
    for _ in range(50):
        step = newton_step(n, n_d, k1, k2)
        n = n - step
        if np.all(np.abs(step) < tol * 1e-3):
            break
    return n, not np.any(np.abs(distorted(n, k1, k2) - n_d) > tol)


@jit(inline="always")
def normalised(u, focal_px, principal_px, k1, k2):
    """Undistorted normalised coordinate of the pixel position ``u`` (a float) and whether it converged (compiled).

    Newton's method on ``distorted(n) = (u - principal) / focal`` until the
    step is below 1e-12 pixels (at most 50 steps), then converged where the
    residual is within 1e-9 pixels.  The camera's
    (:meth:`ballscan.geometry.camera.LineScanCamera.backproject`, on
    arrays) steps until every element's step is that small; the few more
    steps there change ``n`` below that.
    """
    n_d = (u - principal_px) / focal_px
    if k1 == 0.0 and k2 == 0.0:
        return n_d, True
    tol = 1e-9 / focal_px
    n = n_d
    for _ in range(50):
        step = newton_step(n, n_d, k1, k2)
        n = n - step
        if abs(step) < tol * 1e-3:
            break
    return n, abs(distorted(n, k1, k2) - n_d) <= tol
