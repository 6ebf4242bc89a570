"""Pixel coverage of the averaged silhouette, and the whitened residuals of fitted pixels with their Jacobian.

A pixel of a line-scan image integrates the ball's chord over its own width,
its height and the exposure (the averaged model of
:mod:`ballscan.model.averaged`, the paper's dynamic sphere of first Eq. (8)
seen through the camera of Eq. (1)-(2)).  :func:`pixel_coverage` sums the
model's chord samples over pixels; :func:`pixel_residuals` compares that
coverage, times the ball's relative surface brightness and a free
brightness per group of pixels, with measured pixels, and
:func:`pixel_residuals_jacobian` differentiates those residuals with respect
to ``theta`` (the refinement's Jacobian, Eq. (7)-(10)).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..compiled import as_arg
from ._forward_kernels import coverage_grid
from ._forward_kernels import pixel_residuals as _kernel_pixel_residuals
from ._forward_kernels import pixel_residuals_jacobian as _kernel_pixel_residuals_jacobian
from ..geometry.camera import LineScanCamera
from .averaged import _model_core
from .silhouette import _gauss

__all__ = ["PixelWindows", "pixel_coverage", "pixel_residuals", "pixel_residuals_jacobian"]


@dataclass(frozen=True)
class PixelWindows:
    """Measured pixels to fit, packed per line in the compiled kernels' layout.

    Each of ``n_rows`` lines holds up to ``K`` usable pixels, left-aligned;
    unused slots have ``mask`` False, no weight and no value.

    Attributes
    ----------
    t_s : ndarray (n_rows,)
        Line centre times, s.
    cols_px : ndarray (n_rows, K)
        Pixel centres, pixels (an unused slot repeats the line's first one).
    mask : ndarray of bool (n_rows, K)
        Usable slots.
    values : ndarray (n_rows, K)
        Measured pixel values normalised by the ball's contrast (0 where unused).
    weights : ndarray (n_rows, K)
        1 / sigma of each value (0 where unused).
    shade : ndarray (n_rows, K)
        The ball's relative surface brightness at each pixel (1 without a shading model).
    group : ndarray of int64 (n_rows, K)
        Free-brightness group of each pixel, 0 .. n_groups - 1 (-1 where unused).
    n_groups : int
        Number of free brightnesses (nuisance parameters).
    n_pixels : int
        Usable pixels (residuals).
    n_spread : int
        Lines among the rows whose edges the windows replace (both edges).
    nodes : int
        Gauss-Legendre nodes per piece of the exposure in the pixel model (at least).
    """

    t_s: np.ndarray
    cols_px: np.ndarray
    mask: np.ndarray
    values: np.ndarray
    weights: np.ndarray
    shade: np.ndarray
    group: np.ndarray
    n_groups: int
    n_pixels: int
    n_spread: int
    nodes: int


def pixel_coverage(u_lo: np.ndarray, u_hi: np.ndarray, wgt: np.ndarray, cols: np.ndarray) -> np.ndarray:
    """Averaged coverage of pixels by the model's chord samples.

    Parameters
    ----------
    u_lo, u_hi, wgt : ndarray (P, N, 3, n)
        Chord ends (pixels) and weights of each sample of each line
        (``samples`` of :func:`ballscan.model.averaged.averaged_model` with ``return_samples``).
    cols : ndarray (C,) or (N, C)
        Pixel centres (pixels), shared by the lines or one row per line; a
        pixel spans ``[col - 1/2, col + 1/2]``.

    Returns
    -------
    ndarray (P, N, C)
        Sum over the samples of weight times the overlap of ``[lo, hi]``
        with the pixel; NaN on a line with a NaN sample.

    Notes
    -----
    Where a line's pixel centres lie on a grid of unit step (any order, gaps
    allowed: an edge's offsets, the fit's compacted windows, a bound's
    columns) the sum is a histogram of the samples' ends by pixel and its
    cumulative sum (:func:`ballscan.model._forward_kernels.coverage_grid`): O(samples +
    pixels) per line.  Other centres take the direct sum over samples and
    pixels.
    """
    c = np.asarray(cols, dtype=float)
    lead = u_lo.shape[:-2]
    P, N = int(np.prod(lead[:-1])), lead[-1]
    c2 = np.broadcast_to(c, (N, c.shape[-1]))
    if c2.shape[-1] == 0 or not np.all(np.isfinite(c2)):
        return _pixel_coverage_direct(u_lo, u_hi, wgt, c)
    base = c2.min(axis=1)
    rel = c2 - base[:, None]
    idx = np.rint(rel)
    if not np.all(np.abs(rel - idx) < 1e-9):
        return _pixel_coverage_direct(u_lo, u_hi, wgt, c)
    idx = as_arg(idx, np.int64)
    shp = (P, N, -1)
    out = coverage_grid(*(as_arg(a.reshape(shp)) for a in (u_lo, u_hi, wgt)), idx, as_arg(base), int(idx.max()) + 1)
    return out.reshape(lead + (c2.shape[-1],))


def _pixel_coverage_direct(u_lo: np.ndarray, u_hi: np.ndarray, wgt: np.ndarray, cols: np.ndarray) -> np.ndarray:
    """:func:`pixel_coverage` as the direct sum over samples and pixels (any pixel centres; the reference of the grid's)."""
    a = np.asarray(cols, dtype=float) - 0.5
    if a.ndim == 2:
        a = a[:, None, None, :]
    ov = np.clip(np.minimum(u_hi[..., None], a + 1.0) - np.maximum(u_lo[..., None], a), 0.0, 1.0)
    return (wgt[..., None] * ov).sum(axis=(-3, -2))


def pixel_residuals(camera: LineScanCamera, thetas: np.ndarray, R: float, pix: PixelWindows, acc, n_nodes: int) -> np.ndarray:
    """Whitened residuals ``(B_g s cov - p) / sigma`` of the fitted pixels, (P, M).

    ``cov`` is each pixel's coverage averaged over the exposure and the
    pixel's height (``max(n_nodes, pix.nodes)`` Gauss-Legendre nodes per
    piece), ``s`` the ball's relative surface brightness there and ``B_g``
    the brightness of the pixel's group, the least-squares value for each
    parameter set (variable projection): the coverage's shape counts, the
    local level comes from the pixels.

    Parameters
    ----------
    camera : LineScanCamera
    thetas : ndarray (P, 6)
        Parameter sets (s, m, m, m/s, m/s, m/s).
    R : float
        Ball radius, m.
    pix : PixelWindows
    acc : sequence of 3 floats
        Known acceleration, m/s^2.
    n_nodes : int
        Nodes per piece of the edge model (the pixels take at least ``pix.nodes``).
    """
    # (the samples only: no edge spread or validity)
    me = _model_core(camera, thetas, R, pix.t_s, acc, max(n_nodes, pix.nodes), True, full=False)
    P, n_rows = thetas.shape[0], pix.cols_px.shape[0]
    u_lo, u_hi, wgt = (as_arg(a.reshape(P, n_rows, -1)) for a in me.samples)
    return _kernel_pixel_residuals(
        u_lo, u_hi, wgt, pix.cols_px, pix.mask, pix.shade, pix.weights, pix.values, pix.group, pix.n_groups, pix.n_pixels
    )


def pixel_residuals_jacobian(camera: LineScanCamera, theta: np.ndarray, R: float, pix: PixelWindows, n_nodes: int) -> np.ndarray:
    """Exact derivatives (M, 6) of :func:`pixel_residuals` at one parameter set ``theta`` (no acceleration).

    One compiled pass of forward-mode derivatives
    (:func:`ballscan.model._forward_kernels.pixel_residuals_jacobian`) in place of six
    perturbed evaluations of the samples and the coverage; per parameter
    unit (s, m, m/s).
    """
    g, gw = _gauss(max(n_nodes, pix.nodes))
    _, J = _kernel_pixel_residuals_jacobian(
        as_arg(theta), as_arg(pix.t_s), float(R), float(camera.exposure), float(camera.focal_px), float(camera.principal_px),
        float(camera.k1), float(camera.k2), as_arg(g), as_arg(gw),
        pix.cols_px, pix.mask, pix.shade, pix.weights, pix.values, pix.group, pix.n_groups, pix.n_pixels,
    )
    return J
