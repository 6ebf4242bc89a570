"""The edge measurement's kernels (ballscan.measure._edge_kernels) against their numpy forms."""

from __future__ import annotations

import numpy as np

from ballscan.measure import _edge_kernels as K


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
