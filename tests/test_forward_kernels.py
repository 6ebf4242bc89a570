"""The averaged silhouette's kernels (ballscan.model._forward_kernels) against plain numpy references."""

from __future__ import annotations

import numpy as np

from ballscan.geometry.camera import LineScanCamera
from ballscan.geometry.motion import BallMotion
from ballscan.model import _forward_kernels as K
from ballscan.solve.fit import _model_core, param_scale, pixel_coverage

CAM = LineScanCamera(2048, 3000.0, 1023.5, 50000.0, None)
MOTION = BallMotion(0.0335, 0.002, (0.0, 0.01, 3.0), (26.0, 2.0, 15.0))


def _samples(n_sets: int = 3, n_lines: int = 30, nodes: int = 8, seed: int = 0):
    rng = np.random.default_rng(seed)
    thetas = MOTION.to_params()[None] + rng.normal(size=(n_sets, 6)) * param_scale(CAM, MOTION)
    t = 0.002 + np.linspace(-1.1e-3, 1.1e-3, n_lines)
    return t, _model_core(CAM, thetas, MOTION.radius_m, t, (0.0, 0.0, 0.0), nodes, True).samples


def test_coverage_grid_equals_the_overlap_sum():
    # shared columns, each line its own fractional offsets in descending order, and ends beyond the grid
    _, (lo, hi, w) = _samples()
    lo = lo.copy()
    lo[0, 3, 0, 0] = -np.inf
    rng = np.random.default_rng(1)
    for cols in (np.arange(985.0, 1062.0), 1040.3 - np.arange(30.0)[None, :] + rng.integers(-20, 20, size=(lo.shape[1], 1))):
        a = (cols[None, :, None, None, :] if cols.ndim == 2 else cols[None, None, None, None, :]) - 0.5
        ref = (np.clip(np.minimum(hi[..., None], a + 1.0) - np.maximum(lo[..., None], a), 0.0, 1.0) * w[..., None]).sum(axis=(2, 3))
        got = pixel_coverage(lo, hi, w, cols)
        assert np.abs(got - ref).max() < 1e-12
        assert np.array_equal(got == 0.0, ref == 0.0)  # uncovered pixels exactly 0
        assert ref.max() > 0.99


def test_pixel_residuals_equal_coverage_times_shade_and_group_brightness():
    t, (lo, hi, w) = _samples(n_lines=12)
    rng = np.random.default_rng(2)
    n_rows, width = lo.shape[1], 40
    base = np.floor(np.nanmin(lo[0, :, :, :].reshape(n_rows, -1), axis=1)) - 3
    cols = base[:, None] + np.arange(width)[None, :]
    mask = rng.random((n_rows, width)) < 0.8
    shade = 1.0 + 0.05 * rng.standard_normal((n_rows, width))
    wt = np.where(mask, 1.0 / (0.01 + 0.005 * rng.random((n_rows, width))), 0.0)
    group = np.where(mask, np.repeat((np.arange(n_rows) >= n_rows // 2)[:, None], width, axis=1).astype(np.int64), -1)
    cov0 = pixel_coverage(lo[:1], hi[:1], w[:1], cols)[0]
    p = np.where(mask, 0.9 * cov0 * shade + 0.01 * rng.standard_normal((n_rows, width)), 0.0)
    got = K.pixel_residuals(
        *(np.ascontiguousarray(a.reshape(a.shape[0], n_rows, -1)) for a in (lo, hi, w)),
        cols, mask, shade, wt, p, group, 2, int(mask.sum()),
    )
    c = pixel_coverage(lo, hi, w, cols) * shade
    for k in range(lo.shape[0]):
        ck, g = c[k][mask], group[mask]
        ww = wt[mask] ** 2
        B = np.bincount(g, ck * p[mask] * ww) / np.bincount(g, ck * ck * ww)
        ref = (B[g] * ck - p[mask]) * wt[mask]
        assert np.abs(got[k] - ref).max() < 1e-10 * np.abs(ref).max()
