"""Compiled loops of the edge measurement: the edge windows' sums, the walks, the levels and the finished edges.

:mod:`ballscan.measure.edges` measures a ball's edges on its crop in two
passes; as numpy these are some hundred expressions of a few microseconds
each on the box (the rough edges, the shot noise's sigmas, the lines'
summed coverage) or on the edges' rows (the level gradients and their
running medians, the shading decision per side, the levels, edges and
variances, the usable edges and the limb levels' pixel centres).  Each loop
does the same arithmetic in the same order (sums in numpy's pairwise order,
:func:`ballscan.compiled.pairwise_sum`), so the values are the same bit for
bit.
"""

from __future__ import annotations

import math

import numpy as np

from ..compiled import jit, pairwise_sum


@jit()
def walk_edges(p: np.ndarray, k_left: np.ndarray, k_right: np.ndarray, has_signal: np.ndarray, floor_p: np.ndarray, fraction: float, max_walk: int):
    """The rough edges of :func:`ballscan.measure.edges._edge_pass` walked outwards towards a darker (shaded) limb.

    On each line with signal, the left edge ``k`` moves to ``k - 1`` while
    that pixel holds ``fraction`` of its inner neighbour's value (``k + 1``)
    and at least ``floor_p``, or to ``k - 2`` where pixel ``k - 1`` does not
    but ``k - 2`` does (one pixel of a dim limb lost in the noise), at most
    ``max_walk`` times; the right edge likewise.  Returns new ``(k_left,
    k_right)``.
    """
    n, w = p.shape
    kl = k_left.copy()
    kr = k_right.copy()
    for r in range(n):
        if not has_signal[r]:
            continue
        kl[r] = _walk(p, r, kl[r], -1, floor_p[r], fraction, max_walk)
        kr[r] = _walk(p, r, kr[r], 1, floor_p[r], fraction, max_walk)
    return kl, kr


@jit()
def other_sign_edges(
    q: np.ndarray, k_left: np.ndarray, k_right: np.ndarray, has_signal: np.ndarray, min_peak: np.ndarray, floor_q: np.ndarray, fraction: float,
    max_walk: int, max_gap: int, run: int,
):
    """The rough edges of :func:`ballscan.measure.edges._edge_pass` moved out onto a limb of the other sign.

    ``q`` is the profile of the other sign (``-p``, in units of the ball's
    contrast): a bright ball's side in shadow darker than the backdrop, a
    football's black panel at the limb.  Only lines whose ``q`` peaks above
    ``min_peak`` (their signal's significance, and a depth that a camera's
    sharpening undershoot or a background a few sigmas off does not reach)
    are searched, and only ``run`` pixels in a row that hold ``floor_q`` (3
    noise sigmas) count as the other sign:

    * where the ball's sign holds both rough edges (two pixels in a row at
      ``floor_q`` at each), each edge moves onto such a run that starts within
      ``max_gap`` pixels beyond it (the limb's sign changes over them), else
      onto the outermost run beyond it that also holds ``fraction`` of
      ``q``'s peak;
    * elsewhere (a faint line, whose rough edges may sit on the noise) each
      edge is the first run from the box's end that holds that much of
      ``q``, or the first two pixels in a row at ``floor_q`` of the ball's
      sign (the edge keeps that sign, unwalked); at least one edge of the
      other sign, else the line keeps its rough edges.

    A moved edge is walked outwards as :func:`walk_edges` walks.

    Returns
    -------
    k_left, k_right : ndarray of int64 (n,)
    sign_left, sign_right : ndarray of int64 (n,)
        -1 where the edge lies on the other sign, +1 elsewhere.
    has_signal : ndarray of bool (n,)
        ``has_signal``, and the lines whose both edges are of the other sign
        (a faint line with one edge of each sign stays without: its edge of
        the ball's sign is not walked).
    """
    n, w = q.shape
    kl = k_left.copy()
    kr = k_right.copy()
    sl = np.ones(n, dtype=np.int64)
    sr = np.ones(n, dtype=np.int64)
    hs = has_signal.copy()
    for r in range(n):
        peak = q[r, 0]
        for j in range(1, w):
            peak = max(peak, q[r, j])
        if not peak > min_peak[r]:
            continue
        f = floor_q[r]
        t = max(fraction * peak, f)
        a, b = k_left[r], k_right[r]
        if has_signal[r] and b - a >= 1 and -q[r, a] >= f and -q[r, a + 1] >= f and -q[r, b] >= f and -q[r, b - 1] >= f:
            kl[r], sl[r] = _other_sign_side(q, r, a, -1, f, t, fraction, max_walk, max_gap, run)
            kr[r], sr[r] = _other_sign_side(q, r, b, 1, f, t, fraction, max_walk, max_gap, run)
        else:
            # from each end inwards, to the first run of either sign
            kl[r], sl[r] = _first_run(q, r, 0, 1, t, f, fraction, max_walk, run)
            kr[r], sr[r] = _first_run(q, r, w - 1, -1, t, f, fraction, max_walk, run)
            if not (sl[r] < 0 or sr[r] < 0) or sl[r] == 0 or sr[r] == 0:
                kl[r], kr[r], sl[r], sr[r] = k_left[r], k_right[r], 1, 1
        hs[r] = has_signal[r] or (sl[r] < 0 and sr[r] < 0)
    return kl, kr, sl, sr, hs


@jit(inline="always")
def _holds(q: np.ndarray, r: int, j: int, step: int, level: float, run: int) -> bool:
    """Whether ``run`` pixels of line ``r`` from ``j`` on (``step``) lie in the box and hold ``q >= level``."""
    w = q.shape[1]
    for i in range(run):
        c = j + i * step
        if c < 0 or c > w - 1 or not q[r, c] >= level:
            return False
    return True


@jit(inline="always")
def _first_run(q: np.ndarray, r: int, start: int, step: int, t: float, floor: float, fraction: float, max_walk: int, run: int):
    """Line ``r``'s first run of either sign from ``start`` on (``step``): ``(k, -1)`` for ``run`` pixels at ``t`` of the other sign (walked outwards), ``(k, 1)`` for two at ``floor`` of the ball's, ``(start, 0)`` where none (see :func:`other_sign_edges`)."""
    w = q.shape[1]
    j = start
    while 0 <= j + step <= w - 1:
        if _holds(q, r, j, step, t, run):
            return _walk(q, r, j, -step, floor, fraction, max_walk), -1
        if -q[r, j] >= floor and -q[r, j + step] >= floor:
            return j, 1
        j += step
    return start, 0


@jit(inline="always")
def _other_sign_side(q: np.ndarray, r: int, k: int, step: int, floor: float, t: float, fraction: float, max_walk: int, max_gap: int, run: int):
    """Line ``r``'s edge ``k`` moved outwards (``step``) onto a limb of the other sign, and its sign (see :func:`other_sign_edges`).

    A run at ``floor`` whose inner end lies within ``max_gap`` pixels beyond
    ``k``; else, further out, the outermost run at ``t``.  ``(k, 1)``
    where neither is found.
    """
    w = q.shape[1]
    for g in range(1, max_gap + 2):
        j = k + g * step
        if j < 0 or j > w - 1:
            break
        if _holds(q, r, j, step, floor, run):
            return _walk(q, r, j, step, floor, fraction, max_walk), -1
    # from the box's end inwards, up to the pixel beside the edge
    j = 0 if step < 0 else w - 1
    while (j < k - 1) if step < 0 else (j > k + 1):
        # the run from its outer end j inwards
        if _holds(q, r, j, -step, t, run) and ((j - step * (run - 1)) < k if step < 0 else (j - step * (run - 1)) > k):
            return _walk(q, r, j, step, floor, fraction, max_walk), -1
        j -= step
    return k, 1


@jit(inline="always")
def _walk(p: np.ndarray, r: int, k: int, step: int, floor: float, fraction: float, max_walk: int) -> int:
    """Pixel ``k`` of line ``r`` walked by ``step`` (-1 left, +1 right), see :func:`walk_edges`."""
    w = p.shape[1]
    for _ in range(max_walk):
        if k < 0 or k > w - 1:
            break
        need = max(floor, fraction * p[r, min(max(k - step, 0), w - 1)])
        c1 = k + step
        c2 = k + 2 * step
        if 0 <= c1 <= w - 1 and p[r, c1] >= need:
            k = c1
        elif 0 <= c2 <= w - 1 and p[r, c2] >= need:
            k = c2
        else:
            break
    return k


@jit()
def inner_differences(p: np.ndarray, sp: np.ndarray, k_left: np.ndarray, k_right: np.ndarray, has_signal: np.ndarray):
    """Second differences inside the segments of :func:`ballscan.measure.edges._edge_pass` (the ball's own noise).

    The pixels at least 3 inside both rough edges of a line with signal
    whose neighbours are such pixels too (not the box's first or last
    column): their second differences ``p[j-1] - 2 p[j] + p[j+1]``, values
    ``p`` and noise ``sp`` in row-major order (numpy's boolean indexing),
    and their count per column.
    """
    n, w = p.shape
    total = 0
    for r in range(n):
        if has_signal[r]:
            total += max(min(k_right[r] - 3, w - 2) - max(k_left[r] + 3, 1) - 1, 0)
    d2 = np.empty(total)
    pv = np.empty(total)
    sv = np.empty(total)
    per_col = np.zeros(w, dtype=np.int64)
    m = 0
    for r in range(n):
        if not has_signal[r]:
            continue
        # inner pixels j0..j1 (columns 1..w-2); "both" needs j-1 and j+1 inner too
        j0 = max(k_left[r] + 3, 1)
        j1 = min(k_right[r] - 3, w - 2)
        for j in range(j0 + 1, j1):
            d2[m] = (p[r, j - 1] - 2.0 * p[r, j]) + p[r, j + 1]
            pv[m] = p[r, j]
            sv[m] = sp[r, j]
            per_col[j] += 1
            m += 1
    return d2, pv, sv, per_col


@jit()
def _level_runs(p, sp, sat, other, r, k, s, ni, n_level, i, lev, deep, pl0, pl1, sl0, sl1, sat_any, oth_any):
    """Row ``i``'s level, deep and deeper runs of :func:`edge_windows` (line ``r``, edge pixel ``k``, sign ``s``).

    Fills ``lev[i], deep[i]`` and the level run's end values and sigmas;
    returns the three runs' sums and sums of squared sigmas and the
    saturated / other ball flags, updated.  A called function, not an
    inline one: inlined, its array arguments cost a reference count pair
    per edge, and :func:`edge_windows` ran 2.2x slower (64 against 29 us
    per ball on the stream bench's balls).
    """
    w = p.shape[1]
    tl = 0.0
    tl2 = 0.0
    td = 0.0
    td2 = 0.0
    tdd = 0.0
    tdd2 = 0.0
    for j in range(n_level):
        a = k + (ni + 1 + j) * s
        lev[i, j] = a
        c = min(max(a, 0), w - 1)
        sat_any = sat_any or sat[r, c]
        oth_any = oth_any or other[r, c]
        if j == 0:
            pl0[i] = p[r, c]
            sl0[i] = sp[r, c]
        if j == n_level - 1:
            pl1[i] = p[r, c]
            sl1[i] = sp[r, c]
        tl += p[r, c]
        tl2 += sp[r, c] * sp[r, c]
        d = k + (ni + 1 + n_level + j) * s
        deep[i, j] = d
        c = min(max(d, 0), w - 1)
        td += p[r, c]
        td2 += sp[r, c] * sp[r, c]
        c = min(max(d + n_level * s, 0), w - 1)
        tdd += p[r, c]
        tdd2 += sp[r, c] * sp[r, c]
    return tl, tl2, td, td2, tdd, tdd2, sat_any, oth_any


@jit()
def edge_windows(
    p: np.ndarray,
    sp: np.ndarray,
    sat: np.ndarray,
    other: np.ndarray,
    k_left: np.ndarray,
    k_right: np.ndarray,
    n_out: np.ndarray,
    n_in: np.ndarray,
    n_level: int,
):
    """The window and level-run sums of every edge estimate of :func:`ballscan.measure.edges._edge_pass`.

    Rows ``4 n``: for each window variant ``v`` (``n_out[v]`` pixels outside
    the rough edge pixel besides the one next to it, ``n_in[v]`` inside) the
    left edges (sign +1) of the ``n`` lines, then the right ones (-1).  A
    window runs from ``k - (n_out + 1) s`` to ``k + n_in s`` (``s`` the
    sign), its level run the ``n_level`` pixels inside it, the deep run the
    next ``n_level`` and the deeper run the next (clipped to the box).  Sums
    in index order (numpy's for fewer than 8 terms: the same values).

    Returns
    -------
    tuple
        ``S`` (window sums), ``sw`` (4n, n_len: window pixels' sigmas, 0
        beyond a shorter window), ``sw2`` (their sums of squares),
        ``L_run``, ``sl2`` (mean and variance of the level run), ``pl0``,
        ``pl1``, ``sl0``, ``sl1`` (its first and last pixels' values and
        sigmas), ``pd``, ``sd2``, ``pdd``, ``sdd2`` (the deep and deeper
        runs' means and variances), ``win_first``, ``win_last``, ``n_win``,
        ``lev``, ``deep`` (4n, n_level: unclipped), ``sgn``, ``lo``, ``hi``
        (the extreme pixels of window and level run), ``inside_box``,
        ``saturated``, ``overlapping`` (a window or level pixel saturated or
        another ball's).
    """
    n, w = p.shape
    nv = n_out.shape[0]
    R = 2 * nv * n
    n_len = 0
    for v in range(nv):
        n_len = max(n_len, n_out[v] + n_in[v] + 2)
    S = np.empty(R)
    sw = np.zeros((R, n_len))
    sw2 = np.empty(R)
    L_run = np.empty(R)
    sl2 = np.empty(R)
    pl0 = np.empty(R)
    pl1 = np.empty(R)
    sl0 = np.empty(R)
    sl1 = np.empty(R)
    pd = np.empty(R)
    sd2 = np.empty(R)
    pdd = np.empty(R)
    sdd2 = np.empty(R)
    win_first = np.empty(R, dtype=np.int64)
    win_last = np.empty(R, dtype=np.int64)
    n_win = np.empty(R, dtype=np.int64)
    lev = np.empty((R, n_level), dtype=np.int64)
    deep = np.empty((R, n_level), dtype=np.int64)
    sgn = np.empty(R, dtype=np.int64)
    lo_px = np.empty(R, dtype=np.int64)
    hi_px = np.empty(R, dtype=np.int64)
    inside_box = np.empty(R, dtype=np.bool_)
    saturated = np.empty(R, dtype=np.bool_)
    overlapping = np.empty(R, dtype=np.bool_)
    nl2 = float(n_level * n_level)
    for i in range(R):
        q = i // n
        r = i - q * n
        v = q // 2
        s = 1 if q % 2 == 0 else -1
        k = k_left[r] if s > 0 else k_right[r]
        no = n_out[v]
        ni = n_in[v]
        length = no + ni + 2
        sgn[i] = s
        n_win[i] = length
        win_first[i] = k - (no + 1) * s
        win_last[i] = k + ni * s
        wmin = min(win_first[i], win_last[i])
        wmax = max(win_first[i], win_last[i])
        lv_a = k + (ni + 1) * s
        lv_b = k + (ni + n_level) * s
        lmin = min(lv_a, lv_b)
        lmax = max(lv_a, lv_b)
        inside_box[i] = wmin >= 0 and wmax < w and lmin >= 0 and lmax < w
        lo_px[i] = min(wmin, lmin)
        hi_px[i] = max(wmax, lmax)
        sat_any = False
        oth_any = False
        tS = 0.0
        tw2 = 0.0
        for j in range(n_len):
            # a shorter window is padded with its last pixel, out of the sums
            off = -(no + 1) + min(j, length - 1)
            c = min(max(k + off * s, 0), w - 1)
            sat_any = sat_any or sat[r, c]
            oth_any = oth_any or other[r, c]
            if j < length:
                tS += p[r, c]
                sw[i, j] = sp[r, c]
            tw2 += sw[i, j] * sw[i, j]
        S[i] = tS
        sw2[i] = tw2
        tl, tl2, td, td2, tdd, tdd2, sat_any, oth_any = _level_runs(
            p, sp, sat, other, r, k, s, ni, n_level, i, lev, deep, pl0, pl1, sl0, sl1, sat_any, oth_any,
        )
        L_run[i] = tl / n_level
        sl2[i] = tl2 / nl2
        pd[i] = td / n_level
        sd2[i] = td2 / nl2
        pdd[i] = tdd / n_level
        sdd2[i] = tdd2 / nl2
        saturated[i] = sat_any
        overlapping[i] = oth_any
    return (S, sw, sw2, L_run, sl2, pl0, pl1, sl0, sl1, pd, sd2, pdd, sdd2, win_first, win_last, n_win, lev, deep, sgn, lo_px, hi_px,
            inside_box, saturated, overlapping)


# np.nan_to_num's value for an infinity
_FLOAT_MAX = float(np.finfo(np.float64).max)


@jit()
def rough_edges(p: np.ndarray, peak: np.ndarray, fraction: float):
    """Each line's first and last pixel whose ``p`` reaches ``fraction`` of its ``peak`` (0 and the last pixel where none does; :func:`ballscan.measure.edges._edge_pass`).

    Returns
    -------
    k_left, k_right : ndarray of int64 (n,)
    """
    n, w = p.shape
    k_left = np.zeros(n, dtype=np.int64)
    k_right = np.full(n, w - 1, dtype=np.int64)
    for r in range(n):
        t = fraction * peak[r]
        for j in range(w):
            if p[r, j] >= t:
                k_left[r] = j
                break
        for j in range(w - 1, -1, -1):
            if p[r, j] >= t:
                k_right[r] = j
                break
    return k_left, k_right


@jit(error_model="numpy")
def shot_noise(p: np.ndarray, sp: np.ndarray, excess: float, p_in: float) -> np.ndarray:
    """The pixels' noise with the ball's shot noise, ``sqrt(sp**2 + excess * clip(q / p_in, 0, 2))`` (:func:`ballscan.measure.edges._edge_pass`).

    ``q`` is each pixel's signal from the lines before and after it (same
    column): the mean of the two neighbours (the one neighbour on the box's
    first and last line; the pixel itself on a one-line box).  Not the
    pixel's own value: a variance that grows with its own noisy value gives
    the pixels that read high less weight, and every weighted estimate that
    uses it (the windows' sums, the matched edges' weights, the pixel fit)
    reads the ball small: on the quick sweep's long balls (R = 0.11 m and
    140 000 lines/s, 8-bit, shot noise, 32 seeds each) the speed read 0.23
    +- 0.015 and 0.08 +- 0.006 sigma of the pixel bound higher than with the
    neighbours' signal (the same images).  Their noise is independent of the
    pixel's; where the coverage changes from line to line (a ball's ends)
    their mean still follows it to first order.  The clip keeps NaN, as
    numpy's does.
    """
    n, w = p.shape
    out = np.empty((n, w))
    for r in range(n):
        for j in range(w):
            if n < 2:
                q = p[r, j]
            elif r == 0:
                q = p[1, j]
            elif r == n - 1:
                q = p[n - 2, j]
            else:
                q = 0.5 * (p[r - 1, j] + p[r + 1, j])
            t = q / p_in
            if t == t:
                t = t if t > 0.0 else 0.0
                t = t if t < 2.0 else 2.0
            out[r, j] = math.sqrt(sp[r, j] * sp[r, j] + excess * t)
    return out


@jit(error_model="numpy")
def line_coverage(p: np.ndarray, sp: np.ndarray, k_left: np.ndarray, k_right: np.ndarray, has_signal: np.ndarray, c0: int):
    """Each line's summed coverage, its sigma and its centroid (:func:`ballscan.measure.edges._edge_pass`).

    Over the columns ``k_left - 3`` to ``k_right + 3`` of a line with
    signal, else the whole line: ``area = sum p``, ``area_sig = sqrt(sum
    sp^2)`` and ``centroid = sum p (j + c0) / area``, NaN unless ``area >
    3 area_sig``.  Each sum is numpy's of the line with zeros outside the
    columns (pairwise, :func:`pairwise_sum`).
    """
    n, w = p.shape
    area = np.empty(n)
    area_sig = np.empty(n)
    centroid = np.empty(n)
    b_p = np.empty(w)
    b_s = np.empty(w)
    b_c = np.empty(w)
    for r in range(n):
        lo = k_left[r] - 3 if has_signal[r] else 0
        hi = k_right[r] + 3 if has_signal[r] else w - 1
        for j in range(w):
            if lo <= j <= hi:
                b_p[j] = p[r, j]
                b_s[j] = sp[r, j] * sp[r, j]
                b_c[j] = p[r, j] * float(j + c0)
            else:
                b_p[j] = 0.0
                b_s[j] = 0.0
                b_c[j] = 0.0
        area[r] = pairwise_sum(b_p)
        area_sig[r] = math.sqrt(pairwise_sum(b_s))
        centroid[r] = pairwise_sum(b_c) / area[r] if area[r] > 3.0 * area_sig[r] else np.nan
    return area, area_sig, centroid


@jit(error_model="numpy")
def level_gradients(
    pl0: np.ndarray,
    pl1: np.ndarray,
    pd: np.ndarray,
    L_run: np.ndarray,
    sl0: np.ndarray,
    sl1: np.ndarray,
    sd2: np.ndarray,
    sl2: np.ndarray,
    has_signal: np.ndarray,
    n_in: np.ndarray,
    n_level: int,
    slope_lines: int,
):
    """The relative level gradient of each edge row of :func:`ballscan.measure.edges._edge_pass` and its variance as a median of ``slope_lines``.

    Rows as :func:`edge_windows` (``2 n`` per window variant, ``n_in[v]``
    its pixels inside the rough edge): the gradient per pixel across the
    level run (first and last pixels ``pl0, pl1``, sigmas ``sl0, sl1``; with
    a one-pixel run, the deep run ``pd`` against it), times ``-dist /
    L_run`` (``dist`` from the run's centre to the edge pixel's covered
    part, ``L_run`` 1 where 0), NaN on lines without signal; each operation
    as the numpy form's.

    Returns
    -------
    raw_rel, rel_var, rel_sig : ndarray (R,)
    """
    R = pl0.shape[0]
    per_variant = R // n_in.shape[0]
    raw_rel = np.empty(R)
    rel_var = np.empty(R)
    rel_sig = np.empty(R)
    for i in range(R):
        dist = float(n_in[i // per_variant] + 1) + (n_level - 1) / 2.0 - 0.25
        Lsafe = L_run[i] if abs(L_run[i]) > 0.0 else 1.0
        if n_level >= 2:
            grad = (pl1[i] - pl0[i]) / float(n_level - 1)
            g_var = (sl1[i] * sl1[i] + sl0[i] * sl0[i]) / float((n_level - 1) ** 2)
        else:
            grad = (pd[i] - L_run[i]) / float(n_level)
            g_var = (sd2[i] + sl2[i]) / float(n_level**2)
        raw_rel[i] = -dist * grad / Lsafe if has_signal[i] else np.nan
        rel_var[i] = dist * dist * g_var / (Lsafe * Lsafe) * (math.pi / 2.0) / float(max(slope_lines, 1))
        rel_sig[i] = math.sqrt(rel_var[i])
    return raw_rel, rel_var, rel_sig


@jit(inline="always")
def _nan_last_less(a: float, b: float) -> bool:
    """``a`` sorts before ``b`` in numpy's order (NaN last)."""
    return a < b or (b != b and a == a)


@jit()
def running_medians(x: np.ndarray, n_blocks: int, n: int) -> np.ndarray:
    """The running median of :func:`ballscan.measure.edges._running_median` over each of ``n_blocks`` equal blocks of ``x`` (the edges' four sides at once).

    The same values: each window is kept sorted in numpy's order (NaN last)
    and, among equal values, in index order, as :func:`running_median`'s
    insertion sort leaves it; a step drops the oldest entry and inserts the
    newest instead of sorting the window anew (whose unpredictable
    comparisons were most of its time on the crops).
    """
    size = x.shape[0] // n_blocks
    h = n // 2
    wl = 2 * h + 1
    out = np.empty(x.shape[0])
    buf = np.empty(wl)
    idx = np.empty(wl, dtype=np.int64)
    for blk in range(n_blocks):
        x0 = blk * size
        m = 0
        cnt = 0
        for i in range(-h, size + h):
            v = x[x0 + i] if 0 <= i < size else np.nan
            if m == wl:
                # drop the window's oldest entry (index i - wl)
                k = 0
                while idx[k] != i - wl:
                    k += 1
                if math.isfinite(buf[k]):
                    cnt -= 1
                for q in range(k, m - 1):
                    buf[q] = buf[q + 1]
                    idx[q] = idx[q + 1]
                m -= 1
            if math.isfinite(v):
                cnt += 1
            # after every entry it does not sort before (the newest index)
            p = m
            while p > 0 and _nan_last_less(v, buf[p - 1]):
                buf[p] = buf[p - 1]
                idx[p] = idx[p - 1]
                p -= 1
            buf[p] = v
            idx[p] = i
            m += 1
            c = i - h
            if c >= 0:
                if cnt == 0:
                    out[x0 + c] = np.nan
                else:
                    lo = max(cnt - 1, 0) // 2
                    hi = min(cnt // 2, wl - 1)
                    out[x0 + c] = 0.5 * (buf[lo] + buf[hi])
    return out


@jit()
def shaded_sides(rel: np.ndarray, rel_sig: np.ndarray, use: np.ndarray, n_sides: int, threshold: float) -> np.ndarray:
    """The smoothed relative level gradients of :func:`ballscan.measure.edges._edge_pass` that are applied, 0 elsewhere.

    ``rel`` holds ``n_sides`` equal blocks of rows (a window's left or
    right edges); NaN becomes 0 and an infinity the largest float (as
    ``np.nan_to_num``), and a block is zeroed unless the mean of ``|rel| /
    rel_sig`` over its ``use`` rows (numpy's pairwise sum over their count)
    exceeds ``threshold``.
    """
    R = rel.shape[0]
    n = R // n_sides
    out = np.empty(R)
    for i in range(R):
        v = rel[i]
        if v != v:
            v = 0.0
        elif v == np.inf:
            v = _FLOAT_MAX
        elif v == -np.inf:
            v = -_FLOAT_MAX
        out[i] = v
    buf = np.empty(n)
    for q in range(n_sides):
        m = 0
        for i in range(q * n, (q + 1) * n):
            if use[i]:
                buf[m] = abs(out[i]) / rel_sig[i]
                m += 1
        if not (m > 0 and pairwise_sum(buf[:m]) / m > threshold):
            out[q * n : (q + 1) * n] = 0.0
    return out


@jit(error_model="numpy")
def window_edges(
    rel: np.ndarray,
    rel_var: np.ndarray,
    L_run: np.ndarray,
    S: np.ndarray,
    sw2: np.ndarray,
    sl2: np.ndarray,
    n_win: np.ndarray,
    win_first: np.ndarray,
    win_last: np.ndarray,
    sgn: np.ndarray,
    kap: float,
    kap2: float,
):
    """The model-free edges of :func:`ballscan.measure.edges._edge_pass`: level, edge and variance of each edge row.

    The level ``L = L_run (1 + kap rel)`` (``rel`` the applied relative
    gradient, 0 where not), the edge from the window's uncovered length
    ``n_win - S / L`` (``L`` 1 where not positive) at its outermost pixel
    and its variance from the window's and the level run's noise (and the
    gradient's, ``kap2 rel_var``, where applied); each operation as the
    numpy form's (``kap2`` is its ``kap**2``).

    Returns
    -------
    L, e, var : ndarray (R,)
    """
    R = rel.shape[0]
    L = np.empty(R)
    e = np.empty(R)
    var = np.empty(R)
    for i in range(R):
        f = 1.0 + kap * rel[i]
        L[i] = L_run[i] * f
        Ls = L[i] if L[i] > 0.0 else 1.0
        uncovered = n_win[i] - S[i] / Ls
        # left: the window starts at its outermost pixel a; right: ends at b
        if sgn[i] > 0:
            e[i] = (min(win_first[i], win_last[i]) - 0.5) + uncovered
        else:
            e[i] = (max(win_first[i], win_last[i]) + 0.5) - uncovered
        Ls2 = Ls * Ls
        u = S[i] / Ls2
        v = sw2[i] / Ls2 + u * u * sl2[i] * (f * f)
        c = S[i] / Ls
        var[i] = v + (c * c * kap2 * rel_var[i] if rel[i] != 0.0 else 0.0)
    return L, e, var


@jit(error_model="numpy")
def finished_edges(
    e: np.ndarray,
    var: np.ndarray,
    L: np.ndarray,
    S: np.ndarray,
    n_win: np.ndarray,
    dlev: np.ndarray,
    run_ok: np.ndarray,
    L_run: np.ndarray,
    usable: np.ndarray,
    has_signal: np.ndarray,
    spoiled: np.ndarray,
    c0: int,
):
    """The per-line fields of :func:`ballscan.measure.edges._finish` from the edges' rows (4 n: narrow left, right, wide left, right).

    Each edge is usable where ``usable``, its level run is (``run_ok``) and
    its level plausible: ``L > L_run / 2`` and the uncovered length ``n_win
    - S / L`` (L 1 where not positive) within ``[-0.5, n_win + 0.5]``.  On
    the lines with signal the edges ``e + c0`` (sensor pixels), their sigmas
    ``sqrt(var)`` and the narrow edges' texture ``S / L * dlev / L``, NaN on
    the others; each line's level (the mean of a usable pair's, or the one
    usable, NaN) and whether it is an end line (signal, no usable pair, not
    ``spoiled``).

    Returns
    -------
    ok : ndarray of bool (4 n,)
    edge, sigma : ndarray (4, n)
        By window and side, as the rows.
    texture : ndarray (2, n)
        Narrow window, left and right.
    level : ndarray (n,)
    end_line : ndarray of bool (n,)
    """
    R = e.shape[0]
    n = R // 4
    ok = np.empty(R, dtype=np.bool_)
    for i in range(R):
        Ls = L[i] if L[i] > 0.0 else 1.0
        uncovered = n_win[i] - S[i] / Ls
        ok[i] = usable[i] and run_ok[i] and L[i] > 0.5 * L_run[i] and uncovered > -0.5 and uncovered < n_win[i] + 0.5
    edge = np.empty((4, n))
    sig = np.empty((4, n))
    tex = np.empty((2, n))
    level = np.empty(n)
    end_line = np.empty(n, dtype=np.bool_)
    for r in range(n):
        hs = has_signal[r]
        for q in range(4):
            i = q * n + r
            edge[q, r] = e[i] + c0 if hs else np.nan
            sig[q, r] = math.sqrt(var[i]) if hs else np.nan
            if q < 2:
                Ls = L[i] if L[i] > 0.0 else 1.0
                tex[q, r] = (S[i] / Ls) * dlev[i] / Ls if hs else np.nan
        ok_l = ok[r]
        ok_r = ok[n + r]
        if ok_l and ok_r:
            level[r] = 0.5 * (L[r] + L[n + r])
        elif ok_l:
            level[r] = L[r]
        elif ok_r:
            level[r] = L[n + r]
        else:
            level[r] = np.nan
        end_line[r] = hs and not (ok_l and ok_r) and not spoiled[r]
    return ok, edge, sig, tex, level, end_line


@jit()
def limb_pixels(rows: np.ndarray, sgn: np.ndarray, win_first: np.ndarray, win_last: np.ndarray, n_win: np.ndarray, lev: np.ndarray, deep: np.ndarray):
    """The pixel centres of :func:`limb_levels`'s rows ``rows`` of the edges of :func:`ballscan.measure.edges._edge_pass`.

    Each row's window from its outermost pixel inwards (as many as the
    longest window of the rows: ``kw``), then its level run ``lev`` and the
    run inside it ``deep`` (box pixels, as float).

    Returns
    -------
    sg : ndarray (R,)
        The rows' sides as float (+1 left, -1 right).
    px : ndarray (R, kw + 2 n_level)
    kw : int
    """
    R = rows.shape[0]
    n_level = lev.shape[1]
    kw = 0
    for i in range(R):
        kw = max(kw, n_win[rows[i]])
    sg = np.empty(R)
    px = np.empty((R, kw + 2 * n_level))
    for i in range(R):
        r = rows[i]
        sg[i] = float(sgn[r])
        first = min(win_first[r], win_last[r]) if sg[i] > 0 else max(win_first[r], win_last[r])
        for k in range(kw):
            px[i, k] = first + sg[i] * k
        for j in range(n_level):
            px[i, kw + j] = lev[r, j]
            px[i, kw + n_level + j] = deep[r, j]
    return sg, px, kw


@jit()
def finite_rows(a: np.ndarray) -> np.ndarray:
    """``np.all(np.isfinite(a), axis=1)`` of a 2-D array (each row stops at its first non-finite value)."""
    n, w = a.shape
    out = np.ones(n, dtype=np.bool_)
    for r in range(n):
        for j in range(w):
            if not math.isfinite(a[r, j]):
                out[r] = False
                break
    return out


def warm_up() -> None:
    """Load (or compile) this module's kernels now, on tiny inputs (see :func:`ballscan.pipeline.warmup.warm_up`)."""
    prof = np.zeros((1, 8))
    k0 = np.zeros(1, dtype=np.int64)
    k1 = np.full(1, 7, dtype=np.int64)
    yes = np.ones(1, dtype=np.bool_)
    walk_edges(prof, k0, k1, yes, np.zeros(1), 0.25, 1)
    other_sign_edges(prof, k0, k1, yes, np.ones(1), np.ones(1), 0.25, 1, 2, 3)
    inner_differences(prof, prof, k0, k1, yes)
    flags = np.zeros((1, 8), dtype=np.bool_)
    edge_windows(prof, prof, flags, flags, k0, k1, k0, k0, 1)
    rough_edges(prof, np.ones(1), 0.25)
    shot_noise(prof, prof, 1.0, 1.0)
    line_coverage(prof, prof, k0, k1, yes, 0)
    rows4 = np.ones(4)
    flags4 = np.ones(4, dtype=np.bool_)
    ints4 = np.ones(4, dtype=np.int64)
    running_medians(rows4, 4, 3)
    level_gradients(rows4, rows4, rows4, rows4, rows4, rows4, rows4, rows4, flags4, np.zeros(2, dtype=np.int64), 2, 9)
    shaded_sides(rows4, rows4, flags4, 4, 2.0)
    window_edges(rows4, rows4, rows4, rows4, rows4, rows4, ints4, ints4, ints4, ints4, 1.0, 1.0)
    finished_edges(rows4, rows4, rows4, rows4, ints4, rows4, flags4, rows4, flags4, yes, yes, 0)
    limb_pixels(k0, ints4, ints4, ints4, ints4, np.zeros((4, 2), dtype=np.int64), np.zeros((4, 2), dtype=np.int64))
    finite_rows(prof)
