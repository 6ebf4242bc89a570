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
        # all lines stepped at once: to the next pixel, or over one to the one after it (against the pixel inside k)
        for k, step in ((kl, -1), (kr, 1)):
            for _ in range(12):
                need = np.maximum(floor_p, 0.25 * p[rows, np.clip(k - step, 0, w - 1)])
                c1, c2 = k + step, k + 2 * step
                p1 = p[rows, np.clip(c1, 0, w - 1)]
                p2 = p[rows, np.clip(c2, 0, w - 1)]
                one = has_signal & (c1 >= 0) & (c1 <= w - 1) & (p1 >= need)
                two = has_signal & ~one & (c2 >= 0) & (c2 <= w - 1) & (p2 >= need)
                if not (one | two).any():
                    break
                k[:] = np.where(one, c1, np.where(two, c2, k))
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


# the first pass's compiled loops against the numpy forms they replace
def _expected_signal_numpy(p):
    """Each pixel's signal for its noise model from its column neighbours."""
    if p.shape[0] < 2:
        return p
    q = np.empty_like(p)
    q[1:-1] = 0.5 * (p[:-2] + p[2:])
    q[0] = p[1]
    q[-1] = p[-2]
    return q


def _profile(rng, n, w):
    """A noisy box profile with ties, zeros of both signs, NaN and infinities."""
    p = rng.standard_normal((n, w)) * 10.0 ** rng.uniform(-3, 1, (n, w))
    p[rng.random((n, w)) < 0.05] = 0.0
    p[rng.random((n, w)) < 0.05] = -0.0
    p[rng.random((n, w)) < 0.02] = np.nan
    p[rng.random((n, w)) < 0.01] = np.inf
    return p


def test_shot_noise_is_the_numpy_forms_bit_for_bit():
    from ballscan.measure._edge_kernels import shot_noise

    rng = np.random.default_rng(11)
    for n, w in ((1, 7), (2, 5), (3, 9), (40, 70), (90, 150)):
        p = _profile(rng, n, w)
        sp = np.abs(rng.standard_normal((n, w))) * 0.01 + 1e-12
        excess, p_in = float(rng.uniform(1e-5, 1e-3)), float(rng.uniform(0.3, 1.5))
        with np.errstate(invalid="ignore"):
            want = np.sqrt(sp**2 + excess * np.clip(_expected_signal_numpy(p) / p_in, 0.0, 2.0))
        assert np.array_equal(shot_noise(p, sp, excess, p_in), want, equal_nan=True), (n, w)


def test_shaded_sides_is_the_numpy_forms_bit_for_bit():
    from ballscan.measure._edge_kernels import shaded_sides

    rng = np.random.default_rng(12)
    for trial in range(200):
        n = int(rng.integers(1, 150))
        rel = rng.standard_normal(4 * n) * 0.05 + rng.uniform(-0.1, 0.1)
        rel[rng.random(4 * n) < 0.1] = np.nan
        if trial % 5 == 0:
            rel[rng.integers(0, 4 * n)] = np.inf
        rel_sig = np.abs(rng.standard_normal(4 * n)) * 0.02
        rel_sig[rng.random(4 * n) < 0.1] = 0.0
        use = (rng.random(4 * n) < 0.8) & (rel_sig > 0)
        want = np.nan_to_num(rel)
        for q in range(4):
            u = use[q * n : (q + 1) * n]
            with np.errstate(over="ignore"):
                ratio = np.abs(want[q * n : (q + 1) * n][u]) / rel_sig[q * n : (q + 1) * n][u]
            if not (bool(u.any()) and float(np.mean(ratio)) > 2.0):
                want[q * n : (q + 1) * n] = 0.0
        assert np.array_equal(shaded_sides(rel, rel_sig, use, 4, 2.0), want), trial


def test_line_coverage_is_the_numpy_forms_bit_for_bit():
    from ballscan.measure._edge_kernels import line_coverage

    rng = np.random.default_rng(13)
    for n, w in ((1, 3), (5, 8), (40, 70), (90, 150), (20, 300)):
        p = _profile(rng, n, w)
        p[0] = 0.0  # a line of no area
        sp = np.abs(rng.standard_normal((n, w))) * 0.01
        k_left = rng.integers(-2, w, n)
        k_right = k_left + rng.integers(0, w, n)
        has_signal = rng.random(n) < 0.8
        c0 = int(rng.integers(0, 500))
        jj = np.arange(w)[None, :]
        sel = (jj >= np.where(has_signal, k_left - 3, 0)[:, None]) & (jj <= np.where(has_signal, k_right + 3, w - 1)[:, None])
        area = np.where(sel, p, 0.0).sum(axis=1)
        area_sig = np.sqrt(np.where(sel, sp**2, 0.0).sum(axis=1))
        with np.errstate(invalid="ignore", divide="ignore"):
            centroid = np.where(sel, p * (jj + c0), 0.0).sum(axis=1) / area
        centroid = np.where(area > 3.0 * area_sig, centroid, np.nan)
        got = line_coverage(p, sp, k_left, k_right, has_signal, c0)
        for a, b in zip(got, (area, area_sig, centroid)):
            assert np.array_equal(a, b, equal_nan=True), (n, w)


def test_finished_edges_is_the_numpy_forms_bit_for_bit():
    from ballscan.measure._edge_kernels import finished_edges

    rng = np.random.default_rng(14)
    for n in (1, 7, 80):
        R = 4 * n
        e = rng.uniform(0, 100, R)
        var = np.abs(rng.standard_normal(R)) * 1e-3
        L = rng.uniform(-0.2, 1.5, R)
        L[rng.random(R) < 0.05] = np.nan
        S = rng.uniform(0, 4, R)
        n_win = rng.integers(2, 7, R)
        dlev = np.abs(rng.standard_normal(R)) * 0.01
        run_ok, usable = rng.random(R) < 0.9, rng.random(R) < 0.8
        L_run = rng.uniform(0.5, 1.2, R)
        has_signal, spoiled = rng.random(n) < 0.8, rng.random(n) < 0.1
        c0 = int(rng.integers(0, 300))
        # the numpy form of ballscan.measure.edges._finish
        Ls = np.where(L > 0, L, 1.0)
        uncovered = n_win - S / Ls
        with np.errstate(invalid="ignore"):
            plausible = run_ok & (L > 0.5 * L_run) & (uncovered > -0.5) & (uncovered < n_win + 0.5)
        ok = usable & plausible
        tex = (S / Ls) * dlev / Ls
        q = [slice(i * n, (i + 1) * n) for i in range(4)]
        okL, okR = ok[q[0]], ok[q[1]]
        level = np.where(okL & okR, 0.5 * (L[q[0]] + L[q[1]]), np.where(okL, L[q[0]], np.where(okR, L[q[1]], np.nan)))
        got = finished_edges(e, var, L, S, n_win, dlev, run_ok, L_run, usable, has_signal, spoiled, c0)
        assert np.array_equal(got[0], ok)
        for i in range(4):
            assert np.array_equal(got[1][i], np.where(has_signal, (e + c0)[q[i]], np.nan), equal_nan=True)
            assert np.array_equal(got[2][i], np.where(has_signal, np.sqrt(var)[q[i]], np.nan), equal_nan=True)
        for i in range(2):
            assert np.array_equal(got[3][i], np.where(has_signal, tex[q[i]], np.nan), equal_nan=True)
        assert np.array_equal(got[4], level, equal_nan=True)
        assert np.array_equal(got[5], has_signal & ~(okL & okR) & ~spoiled)


def _running_median_loop(x, n):
    """A single-block running median in plain Python (the reference form): each window sorted by insertion in numpy's order (NaN last), its middle finite ranks averaged."""
    size, h = x.shape[0], n // 2
    wl = 2 * h + 1
    out = np.empty(size)
    for i in range(size):
        buf, cnt = [], 0
        for q in range(wl):
            j = i - h + q
            v = float(x[j]) if 0 <= j < size else np.nan
            cnt += bool(np.isfinite(v))
            p = q
            buf.append(v)
            while p > 0 and (v < buf[p - 1] or (buf[p - 1] != buf[p - 1] and v == v)):
                buf[p] = buf[p - 1]
                p -= 1
            buf[p] = v
        out[i] = np.nan if cnt == 0 else 0.5 * (buf[max(cnt - 1, 0) // 2] + buf[min(cnt // 2, wl - 1)])
    return out


def test_running_medians_are_the_former_kernels_bit_for_bit():
    from ballscan.measure._edge_kernels import running_medians

    rng = np.random.default_rng(15)
    for trial in range(600):
        size, blocks, n = int(rng.integers(1, 50)), int(rng.integers(1, 5)), int(rng.integers(2, 12))
        x = rng.standard_normal(size * blocks)
        if trial % 2:
            x = np.round(2 * x)  # ties
        x[rng.random(x.size) < 0.2] = np.nan
        x[rng.random(x.size) < 0.05] = np.inf
        x[rng.random(x.size) < 0.05] = -np.inf
        zero = rng.random(x.size) < 0.1
        x[zero] = np.where(rng.random(zero.sum()) < 0.5, 0.0, -0.0)
        want = np.concatenate([_running_median_loop(x[b * size : (b + 1) * size].copy(), n) for b in range(blocks)])
        got = running_medians(x, blocks, n)
        fin = np.isfinite(want)
        # the same values, signed zeros too
        assert np.array_equal(np.isnan(got), np.isnan(want)) and np.array_equal(got[~np.isnan(got)], want[~np.isnan(want)]), trial
        assert np.array_equal(np.signbit(got[fin]), np.signbit(want[fin])), trial


def test_level_gradients_and_window_edges_are_the_numpy_forms_bit_for_bit():
    import math

    from ballscan.measure._edge_kernels import level_gradients, window_edges

    rng = np.random.default_rng(16)
    for n_level in (1, 2, 3):
        for n in (1, 9, 70):
            R = 4 * n
            pl0, pl1, pd = (rng.uniform(0.3, 1.2, R) for _ in range(3))
            L_run = rng.uniform(-0.1, 1.2, R)
            L_run[rng.random(R) < 0.05] = 0.0
            sl0, sl1 = (np.abs(rng.standard_normal(R)) * 0.01 for _ in range(2))
            sd2, sl2, sw2 = (np.abs(rng.standard_normal(R)) * 1e-4 for _ in range(3))
            hs4 = rng.random(R) < 0.8
            n_in = np.array([0, 1])
            n_in_r = np.repeat(n_in, 2 * n)
            # the numpy form of ballscan.measure.edges._edge_pass
            grad = (pl1 - pl0) / (n_level - 1) if n_level >= 2 else (pd - L_run) / n_level
            dist = n_in_r + 1 + (n_level - 1) / 2.0 - 0.25
            Lsafe = np.where(np.abs(L_run) > 0, L_run, 1.0)
            raw_rel = np.where(hs4, -dist * grad / Lsafe, np.nan)
            g_var = (sl1**2 + sl0**2) / (n_level - 1) ** 2 if n_level >= 2 else (sd2 + sl2) / n_level**2
            rel_var = (dist**2) * g_var / Lsafe**2 * (math.pi / 2.0) / max(9, 1)
            got = level_gradients(pl0, pl1, pd, L_run, sl0, sl1, sd2, sl2, hs4, n_in, n_level, 9)
            for a, b in zip(got, (raw_rel, rel_var, np.sqrt(rel_var))):
                assert np.array_equal(a, b, equal_nan=True), (n_level, n)

            rel = np.where(rng.random(R) < 0.5, 0.0, np.nan_to_num(raw_rel))
            S = rng.uniform(0, 4, R)
            n_win = rng.integers(2, 7, R)
            win_first = rng.integers(0, 100, R)
            win_last = win_first + rng.integers(-6, 7, R)
            sgn = np.where(rng.random(R) < 0.5, 1, -1)
            kap = float(rng.uniform(0.5, 1.5))
            L = L_run * (1.0 + kap * rel)
            Ls = np.where(L > 0, L, 1.0)
            uncovered = n_win - S / Ls
            e = np.where(sgn > 0, np.minimum(win_first, win_last) - 0.5 + uncovered, np.maximum(win_first, win_last) + 0.5 - uncovered)
            var = sw2 / Ls**2 + (S / Ls**2) ** 2 * sl2 * (1.0 + kap * rel) ** 2
            var = var + np.where(rel != 0, (S / Ls) ** 2 * kap**2 * rel_var, 0.0)
            got = window_edges(rel, rel_var, L_run, S, sw2, sl2, n_win, win_first, win_last, sgn, kap, kap**2)
            for a, b in zip(got, (L, e, var)):
                assert np.array_equal(a, b, equal_nan=True), (n_level, n)


def test_rough_edges_are_the_numpy_forms():
    from ballscan.measure._edge_kernels import rough_edges

    rng = np.random.default_rng(17)
    for n, w in ((1, 1), (3, 8), (40, 70), (120, 80)):
        p = _profile(rng, n, w)
        p[0] = 0.0  # no pixel above a zero peak's fraction but itself
        with np.errstate(invalid="ignore"):
            peak = p.max(axis=1)
            above = p >= 0.25 * peak[:, None]
        k_left, k_right = rough_edges(p, peak, 0.25)
        assert np.array_equal(k_left, np.argmax(above, axis=1)) and np.array_equal(k_right, w - 1 - np.argmax(above[:, ::-1], axis=1)), (n, w)


def test_limb_pixels_and_finite_rows_are_the_numpy_forms():
    from ballscan.measure._edge_kernels import finite_rows, limb_pixels

    rng = np.random.default_rng(18)
    R = 40
    sgn = np.where(rng.random(R) < 0.5, 1, -1)
    win_first = rng.integers(0, 100, R)
    win_last = win_first - sgn * rng.integers(1, 6, R)
    n_win = np.abs(win_last - win_first) + 1
    lev = np.stack([win_last + sgn, win_last + 2 * sgn], axis=1)
    deep = lev + 2 * sgn[:, None]
    rows = np.flatnonzero(rng.random(R) < 0.7)
    # the numpy form of ballscan.measure.edges._limb_levels
    sg = sgn[rows].astype(float)
    k = np.arange(int(n_win[rows].max()))
    first = np.where(sg > 0, np.minimum(win_first, win_last)[rows], np.maximum(win_first, win_last)[rows])
    px = np.concatenate([first[:, None] + sg[:, None] * k[None, :], lev[rows], deep[rows]], axis=1).astype(float)
    got = limb_pixels(rows, sgn, win_first, win_last, n_win, lev, deep)
    assert np.array_equal(got[0], sg) and np.array_equal(got[1], px) and got[2] == k.size
    a = _profile(rng, 60, 30)
    assert np.array_equal(finite_rows(a), np.all(np.isfinite(a), axis=1))
