"""Compiled loops of the fit: its residuals and Jacobian from the selected lines, their selection and the step's matrices.

The fit (:mod:`ballscan.solve.fit`) assembles its residual vector and
Jacobian from the model's edges and areas on the selected lines, picks the
lines, weighs the blocks, and equilibrates and damps the normal matrix on
every iteration; as numpy these are tens of small array operations a call
whose fixed cost dominates on a ball's hundred lines.  Each loop does the
same arithmetic in the same order (sums in numpy's pairwise order,
:func:`ballscan.compiled.pairwise_sum`), so the values are numpy's bits.
"""

from __future__ import annotations

import math

import numpy as np

from ..compiled import jit, pairwise_sum


@jit()
def fit_residuals(
    left: np.ndarray, right: np.ndarray, area: np.ndarray, il: np.ndarray, ir: np.ndarray, ia: np.ndarray, b: float,
    ml: np.ndarray, mr: np.ndarray, ma: np.ndarray, sl: np.ndarray, sr: np.ndarray, sa: np.ndarray, tail: np.ndarray,
) -> np.ndarray:
    """The fit's whitened residuals (:func:`ballscan.solve.fit.fit_motion`): selected edges and areas, then ``tail``.

    ``(left[il] - b - ml) / sl``, ``(right[ir] + b - mr) / sr``, ``(area[ia]
    - ma) / sa`` and ``tail`` (the pixel residuals) in one array, the same
    operations as the numpy expressions.
    """
    nl, nr, na = il.shape[0], ir.shape[0], ia.shape[0]
    r = np.empty(nl + nr + na + tail.shape[0])
    for k in range(nl):
        r[k] = (left[il[k]] - b - ml[k]) / sl[k]
    o = nl
    for k in range(nr):
        r[o + k] = (right[ir[k]] + b - mr[k]) / sr[k]
    o += nr
    for k in range(na):
        r[o + k] = (area[ia[k]] - ma[k]) / sa[k]
    o += na
    for k in range(tail.shape[0]):
        r[o + k] = tail[k]
    return r


@jit()
def fit_jacobian(
    dl: np.ndarray, dr: np.ndarray, da: np.ndarray, il: np.ndarray, ir: np.ndarray, ia: np.ndarray,
    sl: np.ndarray, sr: np.ndarray, sa: np.ndarray, tail: np.ndarray, with_bias: bool,
) -> np.ndarray:
    """The fit's whitened Jacobian (:func:`ballscan.solve.fit.fit_motion`) from per-line derivatives (N, 6).

    Rows ``dl[il] / sl``, ``dr[ir] / sr``, ``da[ia] / sa``, then ``tail``
    (M, 6) (the pixel residuals'); with ``with_bias`` a seventh column, the
    edge bias's ``-1 / sl``, ``1 / sr`` and 0.
    """
    nl, nr, na, nt = il.shape[0], ir.shape[0], ia.shape[0], tail.shape[0]
    J = np.empty((nl + nr + na + nt, 7 if with_bias else 6))
    for k in range(nl):
        for j in range(6):
            J[k, j] = dl[il[k], j] / sl[k]
    o = nl
    for k in range(nr):
        for j in range(6):
            J[o + k, j] = dr[ir[k], j] / sr[k]
    o += nr
    for k in range(na):
        for j in range(6):
            J[o + k, j] = da[ia[k], j] / sa[k]
    o += na
    for k in range(nt):
        for j in range(6):
            J[o + k, j] = tail[k, j]
    if with_bias:
        for k in range(nl):
            J[k, 6] = -1.0 / sl[k]
        for k in range(nr):
            J[nl + k, 6] = 1.0 / sr[k]
        for k in range(nl + nr, J.shape[0]):
            J[k, 6] = 0.0
    return J


@jit()
def block_ratio(r: np.ndarray, sizes) -> float:
    """The largest significant block-mean variance ratio of one side's residuals (:func:`ballscan.solve.uncertainty.block_scale`), else 1.

    numpy's sums (:func:`pairwise_sum`) for the block means and their mean
    square, so that the ratios are those of the numpy expressions.
    """
    best = 1.0
    for B in sizes:
        nb = r.shape[0] // B
        if nb < 4:
            continue
        m2 = np.empty(nb)
        for i in range(nb):
            m = pairwise_sum(r[i * B : (i + 1) * B]) / B
            m2[i] = m * m
        ratio = B * (pairwise_sum(m2) / nb)
        if ratio > 1.0 + 3.0 * math.sqrt(2.0 / nb):
            best = max(best, ratio)
    return best


@jit()
def area_tables(
    area: np.ndarray, area_sigma: np.ndarray, level: np.ndarray, level_sigma: np.ndarray, floor2: float, floor_px2: float
):
    """The fit's levelled areas, their 1-sigma and where they exist (:func:`ballscan.solve.problem.weight_tables`), per line.

    The numpy form's operations, line by line: a NaN ``level_sigma`` counts
    as infinite and an infinite one as the largest float (``np.nan_to_num``
    with ``nan=inf``).
    """
    n = area.shape[0]
    ma = np.empty(n)
    sa = np.empty(n)
    ok = np.empty(n, dtype=np.bool_)
    big = np.finfo(np.float64).max
    for i in range(n):
        rel = level_sigma[i]
        if math.isnan(rel):
            rel = math.inf
        elif math.isinf(rel):
            rel = big if rel > 0.0 else -big
        lev = level[i]
        good = math.isfinite(lev) and lev > 0.05 and math.isfinite(rel)
        ls = lev if good else 1.0
        m = area[i] / ls if good else 0.0
        r = rel if good else 0.0
        rel2 = r * r + floor2
        q = area_sigma[i] / ls
        mp = 0.0 if m < 0.0 else m
        ma[i] = m
        sa[i] = math.sqrt(q * q + rel2 * (mp * mp) + floor_px2) if good else math.inf
        ok[i] = good
    return ma, sa, ok


@jit()
def select_lines(
    presence: np.ndarray, valid: np.ndarray, spread: np.ndarray, left_ok: np.ndarray, right_ok: np.ndarray,
    left: np.ndarray, right: np.ndarray, end_line: np.ndarray, wide: bool, left_wide_ok: np.ndarray,
    right_wide_ok: np.ndarray, left_wide: np.ndarray, right_wide: np.ndarray, max_spread: float, max_spread_wide: float,
    end_line_areas: bool,
):
    """The fit's residual selection (:func:`ballscan.solve.problem.select_lines_of`), line by line.

    Returns the masks ``(use_l, use_r, use_a, wide_l, wide_r)``; the wide
    window's arrays are read only with ``wide``.
    """
    n = presence.shape[0]
    use_l = np.empty(n, dtype=np.bool_)
    use_r = np.empty(n, dtype=np.bool_)
    use_a = np.empty(n, dtype=np.bool_)
    wide_l = np.zeros(n, dtype=np.bool_)
    wide_r = np.zeros(n, dtype=np.bool_)
    for i in range(n):
        full = presence[i] > 0.999 and valid[i]
        narrow = full and spread[i] <= max_spread
        ul = left_ok[i] and narrow and math.isfinite(left[i])
        ur = right_ok[i] and narrow and math.isfinite(right[i])
        if wide:
            between = full and spread[i] > max_spread and spread[i] <= max_spread_wide
            wide_l[i] = left_wide_ok[i] and between and math.isfinite(left_wide[i])
            wide_r[i] = right_wide_ok[i] and between and math.isfinite(right_wide[i])
            ul = ul or wide_l[i]
            ur = ur or wide_r[i]
        # no signal: neither edge measured nor an end line
        no_signal = not (left_ok[i] or right_ok[i] or end_line[i])
        if end_line_areas:
            ua = not (ul or ur) and (end_line[i] or no_signal or (left_ok[i] and right_ok[i]))
        else:
            ua = not (ul or ur) and no_signal
        use_l[i] = ul
        use_r[i] = ur
        use_a[i] = ua
    return use_l, use_r, use_a, wide_l, wide_r


@jit()
def equilibrated(AJ: np.ndarray):
    """Column norms ``cn = sqrt(diag(AJ))`` (1 where not positive) of a normal matrix and ``AJ / outer(cn, cn)``.

    The Levenberg-Marquardt steps' equilibration (:func:`ballscan.solve.solver.levenberg_marquardt`),
    the numpy expressions' operations.
    """
    n = AJ.shape[0]
    cn = np.empty(n)
    for i in range(n):
        c = math.sqrt(AJ[i, i])
        cn[i] = c if c > 0.0 else 1.0
    A = np.empty((n, n))
    for i in range(n):
        for j in range(n):
            A[i, j] = AJ[i, j] / (cn[i] * cn[j])
    return cn, A


@jit()
def damped(A: np.ndarray, lam: float) -> np.ndarray:
    """``A + lam * diag(diag(A))`` (the numpy expression's operations: ``+ lam * 0`` off the diagonal)."""
    n = A.shape[0]
    out = np.empty((n, n))
    for i in range(n):
        for j in range(n):
            d = A[i, i] if i == j else 0.0
            out[i, j] = A[i, j] + lam * d
    return out


@jit()
def on_both_sides(lines: np.ndarray, t: np.ndarray, t_c: float) -> bool:
    """Whether the mask ``lines`` holds lines both before and after ``t_c`` (line times ``t``).

    :func:`ballscan.solve.fit._at_both_ends` in one pass.
    """
    before = False
    after = False
    for i in range(lines.shape[0]):
        if lines[i]:
            before = before or t[i] < t_c
            after = after or t[i] > t_c
    return before and after


@jit()
def loose_rows(
    J: np.ndarray, r: np.ndarray, rows: np.ndarray, sa: np.ndarray, sa_loose: np.ndarray, model: np.ndarray, ma_loose: np.ndarray
):
    """The partial lines' rows made loose and both Jacobians equilibrated (:func:`ballscan.solve.fit._partial_verdict`).

    ``J`` (M, p) and ``r`` (M,) are the levelled fit's whitened Jacobian and
    residuals, ``rows`` the partial lines' rows in them, ``sa`` their
    levelled sigmas, ``sa_loose`` and ``ma_loose`` their loose sigmas and
    areas, ``model`` the model's areas there.  Returns ``(r_l, Jl_n, Jt_n,
    gn)``: the loose residuals, both Jacobians divided by the loose one's
    column norms (1 where 0; summed row by row as numpy's ``norm(axis=0)``)
    and the model's area derivatives on those rows, divided too.
    """
    M, p = J.shape
    n = rows.shape[0]
    J_l = J.copy()
    r_l = r.copy()
    g = np.empty((n, p))
    for k in range(n):
        i = rows[k]
        for j in range(p):
            g[k, j] = J[i, j] * sa[k]
            J_l[i, j] = g[k, j] / sa_loose[k]
        r_l[i] = (model[k] - ma_loose[k]) / sa_loose[k]
    cn = np.zeros(p)
    for i in range(M):
        for j in range(p):
            cn[j] += J_l[i, j] * J_l[i, j]
    for j in range(p):
        c = math.sqrt(cn[j])
        cn[j] = c if c > 0.0 else 1.0
    Jl_n = np.empty((M, p))
    Jt_n = np.empty((M, p))
    for i in range(M):
        for j in range(p):
            Jl_n[i, j] = J_l[i, j] / cn[j]
            Jt_n[i, j] = J[i, j] / cn[j]
    gn = np.empty((n, p))
    for k in range(n):
        for j in range(p):
            gn[k, j] = g[k, j] / cn[j]
    return r_l, Jl_n, Jt_n, gn


def warm_up() -> None:
    """Load (or compile) this module's kernels now, on tiny inputs (see :func:`ballscan.pipeline.warmup.warm_up`)."""
    i1, o1, d6 = np.zeros(1, dtype=np.int64), np.ones(1), np.zeros((1, 6))
    fit_residuals(o1, o1, o1, i1, i1, i1, 0.0, o1, o1, o1, o1, o1, o1, np.zeros(0))
    fit_jacobian(d6, d6, d6, i1, i1, i1, o1, o1, o1, np.zeros((0, 6)), True)
    block_ratio(np.zeros(16), (4, 8, 16))
    area_tables(o1, o1, o1, o1, 0.0, 0.0)
    b1 = np.ones(1, dtype=np.bool_)
    select_lines(o1, b1, o1, b1, b1, o1, o1, b1, True, b1, b1, o1, o1, 0.3, 0.8, True)
    damped(equilibrated(np.eye(2))[1], 1e-3)
    on_both_sides(b1, o1, 0.0)
    loose_rows(d6, o1, i1, o1, o1, o1, o1)
