"""The averaged silhouette's kernels (ballscan.model._forward_kernels) against plain numpy references."""

from __future__ import annotations

import numpy as np
import pytest

from ballscan.geometry.camera import LineScanCamera
from ballscan.geometry.motion import BallMotion
from ballscan.model import _forward_kernels as K
from ballscan.model.averaged import _model_core, averaged_model
from ballscan.model.pixels import pixel_coverage
from ballscan.solve.uncertainty import param_scale

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


@pytest.mark.parametrize("distorted, deg", [(False, 30.0), (True, 60.0), (False, 0.0)])
def test_averaged_edges_jacobian_equals_central_differences(distorted, deg):
    """The compiled derivatives of the averaged edges and area (the Jacobian rows of the ball's ends) against central differences.

    Over 170 lines from before the ball to after it.  Edges: 5e-9 to
    1.6e-6 relative per column with steps of 1e-5 of the parameter scale
    (1e-3 for y0, vy and vz, whose columns a small step leaves to
    round-off); the area's y0 / vy columns are perspective only (a
    hundred times smaller than its other columns), 1e-4 relative.
    """
    from ballscan.model._forward_kernels import averaged_edges_jacobian
    from ballscan.model.silhouette import _gauss

    a = np.radians(deg)
    cam = LineScanCamera(2048, 3000.0, 1023.5, 50000.0, None, k1=-0.05 if distorted else 0.0, k2=0.01 if distorted else 0.0)
    m = BallMotion(0.0335, 0.002, (0.0, 0.01, 3.0), (30.0 * np.cos(a), 1.5, 30.0 * np.sin(a)))
    t = 0.002 + np.linspace(-1.3, 1.3, 170) * m.radius_m / m.velocity_mps[0]
    th = m.to_params()
    g, gw = _gauss(3)
    L, Rr, A, dl, dr, da = averaged_edges_jacobian(th, t, m.radius_m, cam.exposure, cam.focal_px, cam.principal_px, cam.k1, cam.k2, g, gw)
    me = averaged_model(cam, th[None], m.radius_m, t, n_nodes=3)
    assert np.array_equal(L, me.left_px[0]) and np.array_equal(Rr, me.right_px[0]) and np.array_equal(A, me.area_px[0])
    assert (me.presence[0] == 0).sum() > 10  # lines without the ball included
    h = np.array([1e-5, 1e-3, 1e-5, 1e-5, 1e-3, 1e-3]) * param_scale(cam, m)
    J = np.stack([dl, dr, da])
    Jc = np.empty_like(J)
    for j in range(6):
        d = np.zeros(6)
        d[j] = h[j]
        p = averaged_model(cam, (th + d)[None], m.radius_m, t, n_nodes=3)
        q = averaged_model(cam, (th - d)[None], m.radius_m, t, n_nodes=3)
        for i, k in enumerate(("left_px", "right_px", "area_px")):
            Jc[i, :, j] = (getattr(p, k)[0] - getattr(q, k)[0]) / (2 * h[j])
    err = np.linalg.norm(J - Jc, axis=1) / np.linalg.norm(Jc, axis=1)
    assert np.all(err[:2] < 1e-5), err
    assert np.all(err[2, [0, 2, 3, 5]] < 1e-5) and np.all(err[2, [1, 4]] < 1e-3), err


@pytest.mark.parametrize("masks", [False, True])
def test_hybrid_rows_kernel_equals_its_numpy_form(masks):
    """hybrid_jacobian's compiled analytic path gives the chord-and-averaged-model rows of the numpy form bit for bit."""
    from ballscan.model._forward_kernels import averaged_edges_jacobian, chord_edges, hybrid_rows
    from ballscan.model.averaged import JacobianMemo, hybrid_jacobian
    from ballscan.model.silhouette import _gauss

    cam = LineScanCamera(2048, 4200.0, 1023.5, 70000.0, 1.2e-5, k1=-0.05)
    m = BallMotion(0.0335, 0.0017, (0, -0.08, 4.2), (44.5, 3.9, -5.5))
    t = np.arange(-5, 250) / cam.line_rate_hz
    theta = m.to_params()
    R = m.radius_m
    rng = np.random.default_rng(5)
    fd_lines = rng.random(t.size) < 0.1 if masks else None
    needed = rng.random(t.size) < 0.9 if masks else None
    g, gw = _gauss(3)
    _, J, ok, x0, z, _ = chord_edges(theta, t, R, cam.focal_px, cam.principal_px, cam.k1, cam.k2, np.zeros(3))
    dl, dr = J[0], J[1]
    reach = np.abs(x0) + abs(theta[3]) * (cam.exposure / 2.0) + np.maximum(z, 0.0) / (2.0 * cam.focal_px)
    fd = ~ok | (reach > 0.8 * R)
    if masks:
        fd = (fd | fd_lines) & needed
    da = dr - dl
    cam_args = (cam.exposure, cam.focal_px, cam.principal_px, cam.k1, cam.k2)
    _, _, _, fl, fr, fa = averaged_edges_jacobian(theta, t[fd], R, *cam_args, g, gw)
    dl[fd], dr[fd], da[fd] = fl, fr, fa
    none = np.zeros(0, dtype=bool)
    got = hybrid_rows(
        theta, t, R, cam.exposure, cam.focal_px, cam.principal_px, cam.k1, cam.k2, g, gw, 0.8 * R,
        none if fd_lines is None else fd_lines, none if needed is None else needed, masks, masks,
    )
    for a, b in zip(got, (dl, dr, da, fd)):
        assert np.array_equal(a, b)
    assert fd.any() and not fd.all()
    memo = JacobianMemo()
    via = hybrid_jacobian(cam, theta, R, t, param_scale(cam, m), fd_lines=fd_lines, needed=needed, memo=memo, analytic=True)
    assert all(np.array_equal(a, b) for a, b in zip(via, (dl, dr, da))) and np.array_equal(memo.last_fd, fd)
