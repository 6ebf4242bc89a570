"""The compiled kernels against plain numpy references, and their one compiled signature each."""

from __future__ import annotations

import numpy as np
import pytest

from ballscan import _kernels as K
from ballscan.camera import LineScanCamera
from ballscan.fit import _model_core, param_scale, pixel_coverage
from ballscan.motion import BallMotion
from ballscan.shading import surface_normals

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


def test_limb_values_equal_the_surface_normals_and_the_shading_law():
    rng = np.random.default_rng(4)
    n_rows, width = 6, 9
    t_rows = 0.002 + np.linspace(-8e-4, 8e-4, n_rows)
    u = 1020.0 + rng.uniform(-40.0, 40.0, (n_rows, width))
    bg = 100.0 + rng.standard_normal((n_rows, width))
    sharp = np.array([True, False] * (n_rows // 2))
    tk = (np.arange(4) + 0.5) / 4 * CAM.exposure - CAM.exposure / 2
    hk = (np.arange(3) + 0.5) / 3 - 0.5
    light = np.array([-60.0, 80.0, -200.0])
    ambient, scale = 40.0, 700.0
    val, cov = K.limb_values(
        t_rows, CAM.backproject(u), bg, sharp, tk, hk, CAM.focal_px, np.array(MOTION.position_m), np.array(MOTION.velocity_mps),
        np.zeros(3), MOTION.t_c_s, MOTION.radius_m, light, ambient, scale,
    )
    for r in range(n_rows):
        ts, hs = (np.zeros(1), np.zeros(1)) if sharp[r] else (tk, hk)
        hit, n = surface_normals(CAM, MOTION, t_rows[r] + ts[:, None, None], u[r][None, None, :], hs[None, :, None])
        v = np.where(hit, (np.maximum(n @ light, 0.0) + ambient - bg[r]) / scale, 0.0)
        assert np.abs(val[r] - v.mean(axis=(0, 1))).max() < 1e-12
        assert np.array_equal(cov[r], hit.mean(axis=(0, 1)))
    assert 0.0 < cov.mean() < 1.0  # rays on and off the ball


@pytest.mark.slow
def test_every_kernel_compiles_one_signature_only():
    # a second signature (a read-only or strided argument) is compiled when
    # first seen: 0.5 s inside a stream's ball
    from ballscan.estimate import estimate_image
    from ballscan.images import LineImage
    from ballscan.render import Appearance, SensorNoise, render
    from ballscan.stream import preload_estimator

    preload_estimator()
    cam = LineScanCamera(240, 3000.0, 119.5, 50000.0, None)
    m = BallMotion(0.0335, 0.002, (0.0, 0.001, 3.0), (30.0, 0.0, 0.0))
    for prnu in (0.0, 0.008):
        noise = SensorNoise(bits=16, white_dn=1000.0, black_dn=0.0, read_dn=5.0, full_well_e=None, prnu_sigma=prnu)
        r = render(cam, (m, Appearance.flat(0.8)), 200, background_level=0.1, noise=noise, seed=4)
        img = LineImage(r.image.astype(float), float(noise.max_dn), 16, "k")
        for pixels in (False, True):
            estimate_image(img, cam, 0.0335, pixels=pixels)
    for kernel in (K.averaged_samples, K.pixel_residuals, K.pixel_residuals_jacobian, K.coverage_grid, K.chord_edges, K.limb_values):
        assert len(kernel.signatures) == 1, (kernel.__name__, kernel.signatures)
