"""The compiled kernels against plain numpy references, and their one compiled signature each."""

from __future__ import annotations

import numpy as np
import pytest

from ballscan import _kernels as K
from ballscan.geometry.camera import LineScanCamera
from ballscan.model.averaged import _model_core
from ballscan.model.pixels import pixel_coverage
from ballscan.solve.uncertainty import param_scale
from ballscan.geometry.motion import BallMotion
from ballscan.measure.shading import surface_normals

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
    from ballscan.measure.detection import ColumnModel, detect
    from ballscan.pipeline.estimate import estimate_image
    from ballscan.pipeline.recipe import Recipe
    from ballscan.measure.images import LineImage
    from ballscan.model.render import Appearance, SensorNoise, render
    from ballscan.stream.engine import preload_estimator

    preload_estimator()
    cam = LineScanCamera(240, 3000.0, 119.5, 50000.0, None)
    m = BallMotion(0.0335, 0.002, (0.0, 0.001, 3.0), (30.0, 0.0, 0.0))
    for prnu in (0.0, 0.008):
        noise = SensorNoise(bits=16, white_dn=1000.0, black_dn=0.0, read_dn=5.0, full_well_e=None, prnu_sigma=prnu)
        r = render(cam, (m, Appearance.flat(0.8)), 200, background_level=0.1, noise=noise, seed=4)
        img = LineImage(r.image.astype(float), float(noise.max_dn), 16, "k")
        for pixels in (False, True):
            estimate_image(img, cam, 0.0335, recipe=Recipe(pixels=pixels))
        # and on known columns (the stream's engine background: read-only arrays)
        own = detect(img)
        estimate_image(img, cam, 0.0335, columns=ColumnModel(own.background_dn, own.noise_dn))
    for kernel in (K.averaged_samples, K.averaged_edges_jacobian, K.pixel_residuals, K.pixel_residuals_jacobian, K.coverage_grid, K.chord_edges, K.limb_values,
                   K.mode_seek, K.running_medians, K.walk_edges, K.inner_differences, K.edge_windows,
                   K.limb_levels, K.shading_fit, K.line_level_sums, K.level_scatter, K.interior_normals,
                   # session 11's loops of the edges, the fit and the shading pass
                   K.rough_edges, K.shot_noise, K.level_gradients, K.shaded_sides, K.window_edges, K.line_coverage,
                   K.finished_edges, K.finite_rows, K.limb_pixels, K.fit_residuals, K.fit_jacobian, K.area_tables,
                   K.select_lines, K.hybrid_rows, K.block_ratio, K.equilibrated, K.damped, K.on_both_sides, K.loose_rows,
                   K.chord_rows, K.unique_lines, K.level_spans):
        assert len(kernel.signatures) == 1, (kernel.__name__, kernel.signatures)
    # and no kernel of the module the package calls, listed or not, holds a
    # second one (the private helpers are compiled inside the kernels that
    # call them, once per caller's types, with no dispatch at run time)
    dispatchers = [v for k, v in vars(K).items() if not k.startswith("_") and hasattr(v, "signatures") and hasattr(v, "py_func")]
    assert len(dispatchers) > 50
    assert [d.__name__ for d in dispatchers if len(d.signatures) > 1] == []


# ---------------------------------------------------------------------------
# the detection's and the edges' kernels against their former numpy forms
# ---------------------------------------------------------------------------
def _mode_seek_numpy(s, start, sigma, floor):
    """The numpy form of ballscan.measure.detection._mode_seek (one searchsorted over all rows, shifted apart)."""
    w, n = s.shape
    rows = np.arange(w)
    base = s[:, 0].astype(np.float64)
    rng = s[:, -1].astype(np.float64) - base
    span = float(rng.max()) + 1.0
    shift = base - rows * span
    keys = np.subtract(s, shift[:, None], dtype=np.float64).ravel()
    first = rows * n
    row_shift = rows * span
    top = rng + 0.25

    def window(m, half):
        lo = np.minimum(np.maximum(m - half - base, -0.25), top) + row_shift
        hi = np.minimum(np.maximum(m + half - base, -0.25), top) + row_shift
        return np.searchsorted(keys, lo, side="left") - first, np.searchsorted(keys, hi, side="right") - first

    def spread(m, half):
        buf = s - m.astype(s.dtype)[:, None]
        inside = np.abs(buf) <= half.astype(s.dtype)[:, None]
        buf = buf * inside
        k = np.count_nonzero(inside, axis=1)
        kk = np.maximum(k, 1)
        mean = buf.sum(axis=1, dtype=np.float64) / kk
        var = np.einsum("ij,ij->i", buf, buf, dtype=np.float64) / kk - mean * mean
        return np.sqrt(np.maximum(var, 0.0) * kk / np.maximum(kk - 1, 1)), k, mean

    m = start.astype(np.float64).copy()
    sg = np.maximum(sigma.astype(np.float64), floor)
    cnt = np.zeros(w, dtype=np.intp)
    for it in range(4):
        if it == 2:
            sig, k, _ = spread(m, 4.5 * sg)
            sg = np.where(k >= 8, np.maximum(sig, floor), sg)
        a, b = window(m, 4.5 * sg)
        cnt = b - a
        i0 = np.minimum(np.maximum(a + (cnt - 1) // 2, 0), n - 1)
        i1 = np.minimum(np.maximum(a + cnt // 2, 0), n - 1)
        med = 0.5 * (s[rows, i0].astype(np.float64) + s[rows, i1])
        m = np.where(cnt >= 1, med, m)
    sig, k, mean = spread(m, 4.5 * sg)
    sg = np.where(k >= 8, np.maximum(sig, floor), sg)
    return np.where(k >= 1, m + mean, m), sg, cnt


def test_mode_seek_equals_its_numpy_form():
    rng = np.random.default_rng(5)
    for trial in range(40):
        w, n = int(rng.integers(1, 60)), int(rng.integers(2, 300))
        # integer-valued background with a ball over part of the lines, a
        # gain (non-integer values), hot / flat columns and starts off the mode
        x = np.round(rng.normal(100.0, rng.uniform(0.3, 6.0), (n, w)))
        x[: int(rng.integers(0, n)), : int(rng.integers(0, w + 1))] += 500.0
        x[:, rng.random(w) < 0.1] = 7.0
        s = np.sort((x / rng.uniform(0.9, 1.1)).T.astype(np.float32), axis=1)
        start = np.median(s, axis=1).astype(np.float64) + rng.normal(0.0, 3.0, w) * (trial % 2)
        sigma = rng.uniform(0.1, 4.0, w)
        got = K.mode_seek(s, start, sigma, 0.5)
        ref = _mode_seek_numpy(s, start, sigma, 0.5)
        assert np.array_equal(got[2], ref[2])  # the windows: the same index ranges
        # the window means and spreads: numpy's pairwise sums against one running sum
        assert np.allclose(got[0], ref[0], rtol=0, atol=1e-9 * np.abs(ref[0]).max())
        assert np.allclose(got[1], ref[1], rtol=1e-9, atol=0)


def _running_median_numpy(x, n):
    """The numpy form of ballscan.measure.edges._running_median (sorted sliding windows)."""
    h = n // 2
    pad = np.concatenate([np.full(h, np.nan), x, np.full(h, np.nan)])
    win = np.sort(np.lib.stride_tricks.sliding_window_view(pad, 2 * h + 1), axis=1)
    cnt = np.isfinite(win).sum(axis=1)
    rows = np.arange(x.size)
    out = 0.5 * (win[rows, np.maximum(cnt - 1, 0) // 2] + win[rows, np.minimum(cnt // 2, win.shape[1] - 1)])
    return np.where(cnt > 0, out, np.nan)


def test_running_medians_equal_their_numpy_form():
    rng = np.random.default_rng(6)
    for _ in range(200):
        x = np.round(rng.normal(size=int(rng.integers(1, 80))) * 4) / 4  # ties
        x[rng.random(x.size) < rng.random()] = np.nan
        for n in (2, 3, 9, 10, 41):
            got = K.running_medians(x, 1, n)
            assert np.array_equal(got, _running_median_numpy(x, n), equal_nan=True)
            two = K.running_medians(np.concatenate([x, x[::-1]]), 2, n)
            assert np.array_equal(two, np.concatenate([_running_median_numpy(x, n), _running_median_numpy(x[::-1], n)]), equal_nan=True)
    assert np.isnan(K.running_medians(np.full(5, np.nan), 1, 3)).all()


def _edge_profile(seed: int, n: int = 40, w: int = 30):
    """A normalised profile with a ball segment per line (limb shading, noise, some empty lines) and its rough edges."""
    rng = np.random.default_rng(seed)
    j = np.arange(w)[None, :]
    centre = w / 2 + rng.uniform(-3, 3, (n, 1))
    half = rng.uniform(0.0, w / 2 + 3, (n, 1))
    p = np.clip(half - np.abs(j - centre), 0.0, 1.0) * (0.6 + 0.4 * np.sqrt(np.clip(half - np.abs(j - centre), 0, 4) / 4))
    p = p + rng.normal(0.0, 0.02, (n, w))
    sp = 0.02 + 0.01 * rng.random((n, w))
    peak = p.max(axis=1)
    has_signal = peak > 6.0 * 0.02
    above = p >= 0.25 * peak[:, None]
    k_left = np.argmax(above, axis=1)
    k_right = w - 1 - np.argmax(above[:, ::-1], axis=1)
    return p, sp, has_signal, k_left, k_right, rng


def test_walk_edges_equals_its_numpy_form():
    walked = 0
    for seed in range(20):
        p, _, has_signal, k_left, k_right, rng = _edge_profile(seed)
        floor_p = np.full(p.shape[0], rng.uniform(0.0, 0.2))
        w = p.shape[1]
        rows = np.arange(p.shape[0])
        kl, kr = k_left.copy(), k_right.copy()
        # all lines stepped at once, as ballscan.measure.edges._edge_pass did in numpy
        for _ in range(12):
            cand = kl - 1
            pc = p[rows, np.clip(cand, 0, w - 1)]
            step = has_signal & (cand >= 0) & (pc >= 0.25 * p[rows, np.clip(kl + 1, 0, w - 1)]) & (pc >= floor_p)
            if not step.any():
                break
            kl = np.where(step, cand, kl)
        for _ in range(12):
            cand = kr + 1
            pc = p[rows, np.clip(cand, 0, w - 1)]
            step = has_signal & (cand <= w - 1) & (pc >= 0.25 * p[rows, np.clip(kr - 1, 0, w - 1)]) & (pc >= floor_p)
            if not step.any():
                break
            kr = np.where(step, cand, kr)
        got = K.walk_edges(p, k_left, k_right, has_signal, floor_p, 0.25, 12)
        assert np.array_equal(got[0], kl) and np.array_equal(got[1], kr)
        walked += int((kl != k_left).sum() + (kr != k_right).sum())
    assert walked > 0  # the profiles' shaded limbs make the edges walk


def test_inner_differences_equal_their_numpy_form():
    for seed in range(20):
        p, sp, has_signal, k_left, k_right, _ = _edge_profile(seed)
        w = p.shape[1]
        jj = np.arange(w)[None, :]
        inner = has_signal[:, None] & (jj >= k_left[:, None] + 3) & (jj <= k_right[:, None] - 3)
        inner[:, [0, -1]] = False
        d2 = np.zeros_like(p)
        d2[:, 1:-1] = p[:, :-2] - 2.0 * p[:, 1:-1] + p[:, 2:]
        both = inner & np.roll(inner, 1, axis=1) & np.roll(inner, -1, axis=1)
        got = K.inner_differences(p, sp, k_left, k_right, has_signal)
        for g, ref in zip(got, (d2[both], p[both], sp[both], both.sum(axis=0))):
            assert np.array_equal(g, ref)
        assert both.sum() > 50


def test_edge_windows_equal_their_numpy_form():
    for seed in range(12):
        p, sp, has_signal, k_left, k_right, rng = _edge_profile(seed)
        n, w = p.shape
        sat = rng.random((n, w)) < 0.02
        other = rng.random((n, w)) < 0.02
        variants = ((1, 0), (3, 1)) if seed % 2 else ((2, 1), (4, 2))
        n_level = 2 if seed % 3 else 3
        # the numpy form of ballscan.measure.edges._edge_pass
        nv = 2 * len(variants)
        k = np.tile(np.concatenate([k_left, k_right]), len(variants))
        sgn = np.tile(np.concatenate([np.ones(n, dtype=int), -np.ones(n, dtype=int)]), len(variants))[:, None]
        rows4 = np.tile(np.arange(n), nv)[:, None]
        n_len = max(a + b + 2 for a, b in variants)
        offs, masks, nins = [], [], []
        for n_out, n_in in variants:
            off = np.arange(-(n_out + 1), n_in + 1)
            offs.append(np.broadcast_to(np.concatenate([off, np.full(n_len - off.size, off[-1])]), (2 * n, n_len)))
            masks.append(np.broadcast_to(np.arange(n_len) < off.size, (2 * n, n_len)))
            nins.append(np.full(2 * n, n_in))
        win_off, win_mask, n_in_r = np.concatenate(offs), np.concatenate(masks), np.concatenate(nins)[:, None]
        win = k[:, None] + win_off * sgn
        lev = k[:, None] + (n_in_r + 1 + np.arange(n_level)[None, :]) * sgn
        winc, levc = np.clip(win, 0, w - 1), np.clip(lev, 0, w - 1)
        pw = np.where(win_mask, p[rows4, winc], 0.0)
        sw = np.where(win_mask, sp[rows4, winc], 0.0)
        pl, sl = p[rows4, levc], sp[rows4, levc]
        deep_base = n_in_r + 1 + n_level + np.arange(n_level)[None, :]
        deep = np.clip(k[:, None] + deep_base * sgn, 0, w - 1)
        deeper = np.clip(k[:, None] + (deep_base + n_level) * sgn, 0, w - 1)
        allidx = np.concatenate([winc, levc], axis=1)
        ref = (
            pw.sum(axis=1), sw, (sw**2).sum(axis=1), pl.mean(axis=1), (sl**2).sum(axis=1) / n_level**2,
            pl[:, 0], pl[:, -1], sl[:, 0], sl[:, -1],
            p[rows4, deep].mean(axis=1), (sp[rows4, deep] ** 2).sum(axis=1) / n_level**2,
            p[rows4, deeper].mean(axis=1), (sp[rows4, deeper] ** 2).sum(axis=1) / n_level**2,
            k + win_off[:, 0] * sgn[:, 0], k + n_in_r[:, 0] * sgn[:, 0], win_mask.sum(axis=1), lev, k[:, None] + deep_base * sgn, sgn[:, 0],
            np.minimum(win.min(1), lev.min(1)), np.maximum(win.max(1), lev.max(1)),
            (win.min(1) >= 0) & (win.max(1) < w) & (lev.min(1) >= 0) & (lev.max(1) < w),
            sat[rows4, allidx].any(axis=1), other[rows4, allidx].any(axis=1),
        )
        got = K.edge_windows(p, sp, sat, other, k_left, k_right, np.array([v[0] for v in variants]), np.array([v[1] for v in variants]), n_level)
        assert len(got) == len(ref)
        for i, (g, r) in enumerate(zip(got, ref)):
            assert g.shape == r.shape and np.array_equal(g, r), i
        assert got[-2].any() and got[-1].any() and not got[-3].all()  # saturated, overlapping, some windows off the box


# ---------------------------------------------------------------------------
# the stream engine's kernels against the engine's former numpy forms
# ---------------------------------------------------------------------------
def _line_test_numpy(x, lo, span, ocols, bg16, max_off, min_run, offsets):
    """The numpy form of the per-line test (StreamEngine._line_offsets and _line_test before the kernels).

    Returns the lines' offsets and, per hit line, its index, count, first
    and last column.
    """
    max_dn = int(np.iinfo(x.dtype).max)
    d = np.subtract(x, lo)
    off = np.zeros(x.shape[0], dtype=np.int32)
    if offsets:
        wide = np.int16 if x.dtype.itemsize == 1 else np.int64
        sub = x[:, ocols].astype(wide)
        sub <<= 4
        sub -= bg16.astype(wide)
        sub.sort(axis=1)
        m = sub.shape[1]
        med = (sub[:, (m - 1) // 2].astype(np.float64) + sub[:, m // 2]) / 32.0
        off = np.clip(np.rint(med), -max_off, max_off).astype(np.int32)
        moved = np.flatnonzero(off)
        if moved.size:
            d[moved] -= (off % (max_dn + 1)).astype(x.dtype)[moved, None]
    h = np.greater(d, span)
    cand = np.flatnonzero(h.any(axis=1))
    r = h[cand]
    for _ in range(min_run - 1):
        r = r[:, 1:] & r[:, :-1]
    keep = r.any(axis=1)
    sub = r[keep]
    cmax = sub.shape[1] - 1 - np.argmax(sub[:, ::-1], axis=1) + (min_run - 1)
    return off, cand[keep], sub.sum(axis=1), np.argmax(sub, axis=1), cmax


def _random_band_case(rng, dt, trial):
    top = int(np.iinfo(dt).max)
    w, n = int(rng.integers(3, 300)), int(rng.integers(1, 60))
    cap = n + int(rng.integers(0, 50))
    # levels near 0 and the top: the band's modular wrap
    level = rng.uniform(0, top) if trial % 5 else float(rng.choice([2.0, top - 2.0]))
    sig = rng.uniform(0.5, 5.0) * (1 if dt == np.uint8 else float(rng.choice([1, 30])))
    ring = np.clip(np.round(rng.normal(level, sig, (cap, w))), 0, top)
    # a "ball" over some lines and columns (over ~half the sampled columns on
    # some lines: the offset's selection), and per-line flicker
    ring[: int(rng.integers(0, cap + 1)), int(rng.integers(0, w)) :] = rng.uniform(0, top)
    ring += rng.integers(-8, 9, (cap, 1)) * (trial % 2)
    ring = np.clip(ring, 0, top).astype(dt)
    bg = level + rng.normal(0.0, 1.0, w)
    k = rng.uniform(1.0, 6.0) * sig
    lo_f = np.clip(np.floor(bg - k), 0, top)
    hi_f = np.clip(np.ceil(bg + k), 0, top)
    lo_f = np.minimum(lo_f, hi_f)
    ocols = np.unique(np.linspace(0, w - 1, min(int(rng.integers(8, 70)), w)).round().astype(np.intp))
    # small clips (the histogram; every line clipped), large ones (selection only)
    max_off = int(rng.integers(0, 40)) if trial % 7 else int(rng.integers(30, 400))
    return ring, lo_f.astype(dt), (hi_f - lo_f).astype(dt), ocols, np.rint(16 * bg[ocols]).astype(np.int64), max_off


def test_stream_line_test_equals_its_numpy_form():
    rng = np.random.default_rng(11)
    seen_clipped = seen_inner = 0
    for trial in range(300):
        dt = np.uint8 if trial % 3 else np.uint16
        ring, lo, span, ocols, bg16, max_off = _random_band_case(rng, dt, trial)
        cap = ring.shape[0]
        n = int(rng.integers(1, cap + 1))
        min_run, offsets = int(rng.integers(1, 4)), bool(trial % 4)
        first = int(rng.integers(0, cap))  # wraps around the ring's end
        rows = (first + np.arange(n)) % cap
        off, idx, counts, cmin, cmax = _line_test_numpy(ring[rows], lo, span, ocols, bg16, max_off, min_run, offsets)
        off_ring = np.full(cap, -99, dtype=np.int32)
        hit_ring = np.zeros(cap, dtype=np.bool_)
        kernel = K.stream_line_test_u8 if dt == np.uint8 else K.stream_line_test_u16
        got = kernel(ring, first, n, lo, span, ocols, bg16, max_off, min_run, offsets, off_ring, hit_ring)
        assert np.array_equal(off_ring[rows], off), trial
        for a, b in zip(got, (idx, counts, cmin, cmax)):
            assert np.array_equal(a, b), trial
        hit = np.zeros(n, dtype=bool)
        hit[idx] = True
        assert np.array_equal(hit_ring[rows], hit)
        assert np.all(off_ring[np.setdiff1d(np.arange(cap), rows)] == -99)  # other rows untouched
        if offsets:
            seen_clipped += int(np.sum((np.abs(off) == max_off) & (max_off > 0)))
            seen_inner += int(np.sum(np.abs(off) < max_off))
    assert seen_clipped > 100 and seen_inner > 1000  # both sides of the clip were tested


def test_stream_line_offset_cases_by_construction():
    # the offset's four ways: histogram, clipped below / above, selection
    # (the two middle values on either side of the window)
    w = 64
    ocols = np.arange(w, dtype=np.intp)
    bg16 = np.full(w, 100 * 16, dtype=np.int64)
    lo = np.full(w, 90, dtype=np.uint8)
    span = np.full(w, 20, dtype=np.uint8)
    lines = np.full((5, w), 100, dtype=np.uint8)
    lines[0, :] = 103  # inside the window: +3
    lines[1, :] = 40  # far below: clipped to -5
    lines[2, :] = 200  # far above: +5
    lines[3, :32] = 40  # half a ball: the middle values 40 and 200, mean 120
    lines[3, 32:] = 200
    lines[4, :32] = 99  # one middle value in the window, one beyond
    lines[4, 32:] = 250
    off_ring = np.zeros(5, dtype=np.int32)
    K.stream_line_test_u8(lines, 0, 5, lo, span, ocols, bg16, 5, 2, True, off_ring, np.zeros(5, dtype=np.bool_))
    ref = _line_test_numpy(lines, lo, span, ocols, bg16, 5, 2, True)[0]
    assert ref.tolist() == [3, -5, 5, 5, 5]
    assert np.array_equal(off_ring, ref)


def _block_sums_numpy(ring, off_ring, rows):
    """The numpy form of the block update's sums (StreamEngine._update_model before the kernels)."""
    ft = np.float32 if ring.dtype.itemsize == 1 and rows.size <= 240 else np.float64
    s = ring[rows].astype(ft)
    off = off_ring[rows]
    if np.any(off):
        s -= off.astype(ft)[:, None]
    return s.sum(axis=0, dtype=ft).astype(np.float64), np.einsum("ij,ij->j", s, s).astype(np.float64)


def test_stream_block_sums_equal_their_numpy_form():
    rng = np.random.default_rng(12)
    for trial in range(60):
        dt = np.uint8 if trial % 2 else np.uint16
        cap, w = int(rng.integers(2, 400)), int(rng.integers(1, 200))
        ring = rng.integers(0, np.iinfo(dt).max + 1, (cap, w)).astype(dt)
        off_ring = rng.integers(-9, 10, cap).astype(np.int32) * (trial % 3 > 0)
        rows = rng.choice(cap, int(rng.integers(1, min(cap, 240) + 1)), replace=False).astype(np.int64)
        kernel = K.stream_block_sums_u8 if dt == np.uint8 else K.stream_block_sums_u16
        t1, t2 = kernel(ring, off_ring, rows)
        r1, r2 = _block_sums_numpy(ring, off_ring, rows)
        assert np.array_equal(t1, r1) and np.array_equal(t2, r2), trial


def test_stream_kernels_compile_one_signature_only():
    from ballscan.stream.engine import StreamEngine

    cam = LineScanCamera(600, 1100.0, 299.5, 20000.0, None)
    rng = np.random.default_rng(13)
    for dt in (np.uint8, np.uint16):
        eng = StreamEngine(cam, 0.0335, dtype=dt)
        lines = rng.normal(40.0, 2.0, (1500, 600)).round().astype(dt)
        eng.push(lines[:700])
        eng.push(np.ascontiguousarray(lines[700:, :]))
    for kernel in (K.stream_line_test_u8, K.stream_line_test_u16, K.stream_block_sums_u8, K.stream_block_sums_u16):
        assert len(kernel.signatures) == 1, (kernel.__name__, kernel.signatures)
