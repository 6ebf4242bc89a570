"""The fit's kernels (ballscan.solve._fit_kernels) against their numpy forms."""

from __future__ import annotations

import numpy as np
import pytest

from ballscan.geometry.camera import LineScanCamera
from ballscan.geometry.motion import BallMotion


def _serve():
    cam = LineScanCamera(2048, 4200.0, 1023.5, 70000.0, 1.2e-5, k1=-0.05)
    m = BallMotion(0.0335, 0.0017, (0, -0.08, 4.2), (44.5, 3.9, -5.5))
    return cam, m


def test_fit_kernels_equal_their_numpy_forms():
    """The compiled residuals, Jacobian and block ratio give the numpy expressions' values bit for bit."""
    from ballscan.solve._fit_kernels import block_ratio, fit_jacobian, fit_residuals

    rng = np.random.default_rng(7)
    n = 150
    left, right, area = (rng.standard_normal(n) * 30.0 for _ in range(3))
    dl, dr, da = (rng.standard_normal((n, 6)) * 10.0 ** rng.uniform(-3, 6, 6) for _ in range(3))
    use_l, use_r, use_a = (rng.random(n) < p for p in (0.7, 0.6, 0.2))
    il, ir, ia = (np.flatnonzero(u) for u in (use_l, use_r, use_a))
    ml, mr, ma = (rng.standard_normal(i.size) for i in (il, ir, ia))
    sl, sr, sa = (rng.uniform(0.01, 2.0, i.size) for i in (il, ir, ia))
    tail = rng.standard_normal(17)
    b = 0.0123
    r = fit_residuals(left, right, area, il, ir, ia, b, ml, mr, ma, sl, sr, sa, tail)
    ref = np.concatenate([(left[use_l] - b - ml) / sl, (right[use_r] + b - mr) / sr, (area[use_a] - ma) / sa, tail])
    assert np.array_equal(r, ref)
    jp = rng.standard_normal((17, 6))
    for with_bias in (False, True):
        J = fit_jacobian(dl, dr, da, il, ir, ia, sl, sr, sa, jp, with_bias)
        ref = np.vstack([dl[use_l] / sl[:, None], dr[use_r] / sr[:, None], da[use_a] / sa[:, None], jp])
        if with_bias:
            jb = np.concatenate([-1.0 / sl, 1.0 / sr, np.zeros(ma.size + jp.shape[0])])
            ref = np.hstack([ref, jb[:, None]])
        assert J.flags.c_contiguous and np.array_equal(J, ref)
    for size in list(range(0, 70)) + [130, 257, 300]:
        res = rng.standard_normal(size) * rng.uniform(0.5, 3.0) + np.linspace(0.0, rng.uniform(-2, 2), size)
        best = 1.0
        for B in (4, 8, 16):
            nb = res.size // B
            if nb < 4:
                continue
            m = res[: nb * B].reshape(nb, B).mean(axis=1)
            ratio = B * float(np.mean(m * m))
            if ratio > 1.0 + 3.0 * np.sqrt(2.0 / nb):
                best = max(best, ratio)
        assert block_ratio(res, (4, 8, 16)) == best


def test_area_tables_kernel_equals_its_numpy_form():
    """The compiled levelled areas give the numpy expressions' values bit for bit (NaN and infinite sigmas too)."""
    from ballscan.solve._fit_kernels import area_tables

    rng = np.random.default_rng(3)
    n = 300
    area = rng.normal(3.0, 4.0, n)
    area[::37] = np.nan
    area_sigma = rng.uniform(0.01, 1.0, n)
    lev = rng.uniform(-0.2, 1.5, n)
    lev[::11] = np.nan
    lev[5::29] = np.inf
    rel = rng.uniform(0.0, 0.3, n)
    rel[::7] = np.nan
    rel[3::13] = np.inf
    rel[4::17] = -np.inf
    f2, fp2 = 0.002**2, 0.005**2
    with np.errstate(over="ignore", invalid="ignore"):  # an infinite sigma is the largest float, squared
        rel_n = np.nan_to_num(rel, nan=np.inf)
        ok = np.isfinite(lev) & (lev > 0.05) & np.isfinite(rel_n)
        ls = np.where(ok, lev, 1.0)
        ma = np.where(ok, area / ls, 0.0)
        rel2 = np.where(ok, rel_n, 0.0) ** 2 + f2
        sa = np.sqrt((area_sigma / ls) ** 2 + rel2 * np.maximum(ma, 0.0) ** 2 + fp2)
    got = area_tables(area, area_sigma, lev, rel, f2, fp2)
    assert np.array_equal(got[0], ma, equal_nan=True)
    assert np.array_equal(got[1], np.where(ok, sa, np.inf), equal_nan=True)
    assert np.array_equal(got[2], ok) and ok.any() and not ok.all()


@pytest.mark.parametrize("wide, end_line_areas", [(True, True), (False, True), (True, False)])
def test_select_lines_kernel_equals_its_numpy_form(wide, end_line_areas):
    """The compiled residual selection gives the numpy expressions' masks."""
    from ballscan.solve._fit_kernels import select_lines

    rng = np.random.default_rng(11)
    n = 400
    pres = np.where(rng.random(n) < 0.8, 1.0, rng.random(n))
    valid, lo, ro, end, wlo, wro = (rng.random(n) < p for p in (0.95, 0.8, 0.8, 0.15, 0.7, 0.7))
    spread = rng.uniform(0.0, 1.2, n)
    spread[::23] = np.nan
    el, er, ewl, ewr = (np.where(rng.random(n) < 0.1, np.nan, rng.normal(0, 50, n)) for _ in range(4))
    ms, mw = 0.3, 0.8
    full = (pres > 0.999) & valid
    narrow = full & (spread <= ms)
    use_l = lo & narrow & np.isfinite(el)
    use_r = ro & narrow & np.isfinite(er)
    wide_l = np.zeros(n, dtype=bool)
    wide_r = np.zeros(n, dtype=bool)
    if wide:
        between = full & (spread > ms) & (spread <= mw)
        wide_l = wlo & between & np.isfinite(ewl)
        wide_r = wro & between & np.isfinite(ewr)
        use_l, use_r = use_l | wide_l, use_r | wide_r
    no_signal = ~((lo | ro) | end) & ~(lo | ro)
    if end_line_areas:
        use_a = ~(use_l | use_r) & (end | no_signal | (lo & ro))
    else:
        use_a = ~(use_l | use_r) & no_signal
    got = select_lines(pres, valid, spread, lo, ro, el, er, end, wide, wlo, wro, ewl, ewr, ms, mw, end_line_areas)
    for g, ref in zip(got, (use_l, use_r, use_a, wide_l, wide_r)):
        assert g.dtype == bool and np.array_equal(g, ref)
    assert use_a.any() and use_l.any() and (wide_l.any() or not wide)





def test_step_matrix_kernels_equal_their_numpy_forms():
    """The Levenberg-Marquardt step's equilibration and damping give the numpy expressions' matrices bit for bit."""
    from ballscan.solve._fit_kernels import damped, equilibrated

    rng = np.random.default_rng(13)
    for p in (6, 7):
        J = rng.standard_normal((200, p)) * 10.0 ** rng.uniform(-6, 4, p)
        J[:, 1] *= rng.random() < 0.5  # a column of zeros (norm 1)
        AJ = J.T @ J
        cn = np.sqrt(np.diag(AJ))
        cn = np.where(cn > 0, cn, 1.0)
        A = AJ / np.outer(cn, cn)
        got_cn, got_A = equilibrated(AJ)
        assert np.array_equal(got_cn, cn) and np.array_equal(got_A, A, equal_nan=True)
        for lam in (1e-9, 1e-3, 0.1, 1e10):
            ref = A + lam * np.diag(np.diag(A))
            out = damped(A, lam)
            assert np.array_equal(out, ref, equal_nan=True) and np.array_equal(np.signbit(out), np.signbit(ref))


def test_on_both_sides_kernel_equals_its_numpy_form():
    """The compiled test of lines before and after t_c agrees with the numpy expression."""
    from ballscan.solve._fit_kernels import on_both_sides

    rng = np.random.default_rng(17)
    t = np.arange(60) * 1e-4
    t[7] = np.nan
    for _ in range(300):
        lines = rng.random(t.size) < rng.choice([0.02, 0.1, 0.5])
        # a line's own time (neither before nor after) or anywhere
        t_c = float(t[rng.integers(0, t.size)]) if rng.random() < 0.3 else rng.uniform(-1e-3, 7e-3)
        ref = bool(np.any(lines & (t < t_c)) and np.any(lines & (t > t_c)))
        assert on_both_sides(lines, t, t_c) == ref


@pytest.mark.parametrize("p", [6, 7])
def test_loose_rows_kernel_equals_its_numpy_form(p):
    """The partial verdict's loose rows and equilibrated Jacobians equal the numpy expressions' bit for bit."""
    from ballscan.solve._fit_kernels import loose_rows

    rng = np.random.default_rng(19)
    for M in (9, 40, 230):
        J = rng.standard_normal((M, p)) * 10.0 ** rng.uniform(-5, 5, p)
        r = rng.standard_normal(M)
        rows = np.sort(rng.choice(M, 4, replace=False))
        sa, sa_l, model, ma_l = rng.uniform(0.1, 2.0, 4), rng.uniform(0.5, 5.0, 4), rng.normal(3, 1, 4), rng.normal(3, 1, 4)
        g = J[rows] * sa[:, None]
        J_l, r_l = J.copy(), r.copy()
        J_l[rows] = g / sa_l[:, None]
        r_l[rows] = (model - ma_l) / sa_l
        cn = np.linalg.norm(J_l, axis=0)
        cn = np.where(cn > 0, cn, 1.0)
        got = loose_rows(J, r, rows, sa, sa_l, model, ma_l)
        for a, b in zip(got, (r_l, J_l / cn, J / cn, g / cn)):
            assert np.array_equal(a, b)
