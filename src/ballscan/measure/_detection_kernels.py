"""Compiled loops of the detector: the background's mode seeking, the hits' labels and the lines' medians.

A stream measures each ball on a crop of about 150 x 200 pixels within a
latency budget of 10 ms (benchmarks/bench_stream.py).  On arrays that small
the numpy forms of these loops (:mod:`ballscan.measure.detection`) spend
most of their time in the fixed cost of some hundred whole-array
operations; one pass over the data does the same arithmetic.
"""

from __future__ import annotations

import math

import numpy as np

from ..compiled import jit, select_kth


@jit()
def _search_keys(s: np.ndarray, i: int, shift: float, x: float, right: bool) -> int:
    """Number of ``float64(s[i, j]) - shift`` (ascending in ``j``) below ``x`` (``right``: at most ``x``)."""
    lo = 0
    hi = s.shape[1]
    while lo < hi:
        mid = (lo + hi) // 2
        key = np.float64(s[i, mid]) - shift
        if key < x or (right and key == x):
            lo = mid + 1
        else:
            hi = mid
    return lo


@jit()
def _window_spread(s: np.ndarray, i: int, m: float, half: float):
    """Spread, count and mean offset of the values of row ``i`` of ``s`` within ``half`` of ``m``.

    In ``s``'s float32 like :func:`ballscan.measure.detection._mode_seek`'s numpy
    form (offsets ``s - m`` and the window test in float32), the sums in
    float64 (one running sum, where numpy sums pairwise: the same to
    round-off).
    """
    m32 = np.float32(m)
    h32 = np.float32(half)
    k = 0
    t1 = 0.0
    t2 = 0.0
    for j in range(s.shape[1]):
        d = s[i, j] - m32
        if abs(d) <= h32:
            k += 1
            dd = np.float64(d)
            t1 += dd
            t2 += dd * dd
    kk = max(k, 1)
    mean = t1 / kk
    var = t2 / kk - mean * mean
    return math.sqrt(max(var, 0.0) * kk / max(kk - 1, 1)), k, mean


@jit()
def mode_seek(s: np.ndarray, start: np.ndarray, sigma: np.ndarray, floor: float):
    """Mode, noise sigma and final window count of each row of the row-sorted float32 ``s`` (:func:`ballscan.measure.detection._mode_seek`).

    The windows are found as there, by a search among the keys
    ``s - (s[:, 0] - row * span)`` (``span`` one more than the largest
    row's range), here row by row on the same float64 keys, so the windows
    and medians are those of the numpy form; the window means and spreads
    agree to round-off (summation order).
    """
    w, n = s.shape
    centre = np.empty(w)
    sig_out = np.empty(w)
    cnt = np.zeros(w, dtype=np.int64)
    if w == 0 or n == 0:
        return centre, sig_out, cnt
    span = -np.inf
    for i in range(w):
        span = max(span, np.float64(s[i, n - 1]) - np.float64(s[i, 0]))
    span += 1.0
    for i in range(w):
        base = np.float64(s[i, 0])
        top = (np.float64(s[i, n - 1]) - base) + 0.25
        row_shift = i * span
        shift = base - row_shift
        m = start[i]
        sg = max(sigma[i], floor)
        c = 0
        for it in range(4):
            if it == 2:
                sd, k, _ = _window_spread(s, i, m, 4.5 * sg)
                # the spread of a window of fewer than ~8 values is meaningless
                if k >= 8:
                    sg = max(sd, floor)
            half = 4.5 * sg
            lo = min(max(m - half - base, -0.25), top) + row_shift
            hi = min(max(m + half - base, -0.25), top) + row_shift
            a = _search_keys(s, i, shift, lo, False)
            c = _search_keys(s, i, shift, hi, True) - a
            if c >= 1:
                i0 = min(max(a + (c - 1) // 2, 0), n - 1)
                i1 = min(max(a + c // 2, 0), n - 1)
                m = 0.5 * (np.float64(s[i, i0]) + np.float64(s[i, i1]))
        sd, k, mean = _window_spread(s, i, m, 4.5 * sg)
        if k >= 8:
            sg = max(sd, floor)
        # the window's mean, not its median (a median of integer data is an integer)
        if k >= 1:
            m = m + mean
        centre[i] = m
        sig_out[i] = sg
        cnt[i] = c
    return centre, sig_out, cnt


@jit()
def second_level(s: np.ndarray, centre: np.ndarray, half: np.ndarray):
    """Each row's values off its mode and the most of them within ``half`` of one level (:func:`ballscan.measure.detection._column_modes`).

    ``s`` is row-sorted (float32); a row's values beyond ``half[i]`` of
    ``centre[i]`` on the side holding more of them are its tail, and a
    median restricted to ``+-half[i]`` (three rounds from the tail's
    median) finds the tail's densest level. Returns, per row, the tail's
    size and the number of its values within that level's window.
    """
    w, n = s.shape
    tail = np.zeros(w, dtype=np.int64)
    dense = np.zeros(w, dtype=np.int64)
    for i in range(w):
        h = half[i]
        below = _search_keys(s, i, 0.0, centre[i] - h, False)
        above = n - _search_keys(s, i, 0.0, centre[i] + h, True)
        a0, a1 = (0, below) if below >= above else (n - above, n)
        tail[i] = a1 - a0
        if a1 - a0 < 3:
            continue
        m = np.float64(s[i, (a0 + a1) // 2])
        k = 0
        for _ in range(3):
            lo = max(_search_keys(s, i, 0.0, m - h, False), a0)
            hi = min(_search_keys(s, i, 0.0, m + h, True), a1)
            k = hi - lo
            if k <= 0:
                break
            m = 0.5 * (np.float64(s[i, lo + (k - 1) // 2]) + np.float64(s[i, lo + k // 2]))
        dense[i] = max(k, 0)
    return tail, dense


@jit()
def pair_offs(xs: np.ndarray, cl: np.ndarray, clip_at: np.ndarray, tol: np.ndarray, use_gain: bool, stride: int, clipped_any: bool) -> np.ndarray:
    """``offs[i, k, j]`` of :func:`ballscan.measure.clear_lines._pair_offs`: pixel ``j`` of line ``i`` off line ``k``'s after their factor (offset).

    The factor is the median of ``xs[i] / xs[k]`` (``xs[i] - xs[k]``) over
    every ``stride``-th column where neither pixel is clipped (and, for the
    ratio, ``xs[k] > 0``); without clipped pixels a column without a ratio
    leaves no factor (1, or offset 0), as numpy's median of a NaN would.
    """
    m, w = xs.shape
    offs = np.zeros((m, m, w), dtype=np.bool_)
    buf = np.empty((w + stride - 1) // stride)
    for i in range(m):
        for k in range(m):
            q = 0
            gap = False
            for j in range(0, w, stride):
                ok = not (cl[i, j] or cl[k, j])
                if use_gain:
                    ok = ok and xs[k, j] > 0
                if ok:
                    buf[q] = xs[i, j] / xs[k, j] if use_gain else xs[i, j] - xs[k, j]
                    q += 1
                else:
                    gap = True
            if q == 0 or (gap and not clipped_any):
                c = 1.0 if use_gain else 0.0
            else:
                # the median by selection in place (numpy's value: the mean
                # of the middle two of an even count)
                part = buf[:q]
                c = select_kth(part, q, q // 2)
                if q % 2 == 0:
                    c = (part[: q // 2].max() + c) / 2.0
            f = math.sqrt(0.5 * (1.0 + c**2)) if use_gain else 1.0
            for j in range(w):
                t = tol[j] * f
                pred = c * xs[k, j] if use_gain else xs[k, j] + c
                off = abs(xs[i, j] - pred) > t
                if clipped_any:
                    if cl[i, j]:
                        off = pred < clip_at[i] - t
                    if cl[k, j]:
                        clip_k = c * clip_at[k] if use_gain else clip_at[k] + c
                        off = (xs[i, j] < clip_k - t) and not cl[i, j]
                offs[i, k, j] = off
    return offs


@jit()
def scale_counts(rows: np.ndarray, grid: np.ndarray, profile: np.ndarray, half: np.ndarray, use_gain: bool, sat: float) -> np.ndarray:
    """Pixels of each line of ``rows`` within ``half`` of each scale's (offset's) background, or clipped where it reaches the clip (:func:`ballscan.measure.clear_lines.line_levels`)."""
    n, w = rows.shape
    out = np.zeros((n, grid.size), dtype=np.int64)
    for i in range(n):
        for g in range(grid.size):
            c = grid[g]
            e = 0
            for j in range(w):
                pred = c * profile[j] if use_gain else profile[j] + c
                r = rows[i, j]
                e += (abs(r - pred) <= half[j]) | ((r >= sat) & (pred >= sat - half[j]))
            out[i, g] = e
    return out


@jit()
def on_first(x: np.ndarray, first: np.ndarray, profile: np.ndarray, half: np.ndarray, use_gain: bool, sat: float) -> np.ndarray:
    """Pixels of each line of ``x`` (float32, widened) within ``half`` of its first scale's (offset's) background, or clipped where that reaches the clip."""
    n, w = x.shape
    out = np.zeros(n, dtype=np.int64)
    for i in range(n):
        c = first[i]
        e = 0
        for j in range(w):
            pred = c * profile[j] if use_gain else profile[j] + c
            r = np.float64(x[i, j])
            e += (abs(r - pred) <= half[j]) | ((r >= sat) & (pred >= sat - half[j]))
        out[i] = e
    return out


@jit(inline="always")
def _root(parent: np.ndarray, q: int) -> int:
    """Root of ``q`` in the union-find forest ``parent`` (path halving)."""
    while parent[q] != q:
        parent[q] = parent[parent[q]]
        q = parent[q]
    return q


@jit(inline="always")
def _grown(a: np.ndarray, size: int) -> np.ndarray:
    """A copy of the 1-D ``a`` with room for ``size`` entries."""
    out = np.empty(size, dtype=a.dtype)
    out[: a.size] = a
    return out


@jit()
def label_hits(x: np.ndarray, gain: np.ndarray, b: np.ndarray, offset: np.ndarray, thr: np.ndarray):
    """8-connected labels, sizes and boxes of the pixels with ``|x - (gain b + offset)| > thr`` (:func:`ballscan.measure.detection.detect`).

    The test is in float32 like the numpy form (``x``, ``gain``, ``b``,
    ``offset`` and ``thr`` float32).  The labels are numbered as
    ``scipy.ndimage.label`` (structure ``ones((3, 3))``) numbers them, in
    the raster order of each component's first pixel, so ``lab`` (int32)
    is its array; ``sizes[k]`` and ``boxes[k] = (line_start, line_stop,
    col_start, col_stop)`` belong to label ``k + 1`` (``np.bincount`` and
    ``ndi.find_objects`` of it).  Runs of hit pixels along each line are
    joined (union-find) with the runs of the line above that touch them.
    """
    n, w = x.shape
    lab = np.zeros((n, w), dtype=np.int32)
    # room for the runs, doubled when a line might not fit (a line holds at
    # most (w + 1) // 2; all lines that many would be a large image's
    # memory many times over)
    per_line = (w + 1) // 2
    cap = 4 * n + per_line
    run_line = np.empty(cap, dtype=np.int64)
    run_start = np.empty(cap, dtype=np.int64)
    run_stop = np.empty(cap, dtype=np.int64)
    parent = np.empty(cap, dtype=np.int64)
    row = np.empty(w, dtype=np.bool_)
    n_run = 0
    prev_first = 0  # the runs of the line above: [prev_first, first)
    for i in range(n):
        first = n_run
        if n_run + per_line > cap:
            cap = 2 * cap + per_line
            run_line = _grown(run_line, cap)
            run_start = _grown(run_start, cap)
            run_stop = _grown(run_stop, cap)
            parent = _grown(parent, cap)
        g = gain[i]
        o = offset[i]
        # the test first, over the whole line (a loop without branches)
        for j in range(w):
            row[j] = abs(x[i, j] - (g * b[j] + o)) > thr[j]
        j = 0
        while j < w:
            if not row[j]:
                j += 1
                continue
            start = j
            j += 1
            while j < w and row[j]:
                j += 1
            run_line[n_run] = i
            run_start[n_run] = start
            run_stop[n_run] = j
            parent[n_run] = n_run
            n_run += 1
        # 8-connected: runs [a, b) and [c, d) of neighbouring lines touch where a <= d and c <= b
        q = prev_first
        for r in range(first, n_run):
            while q < first and run_stop[q] < run_start[r]:
                q += 1
            k = q
            while k < first and run_start[k] <= run_stop[r]:
                ra = _root(parent, r)
                rb = _root(parent, k)
                if ra < rb:
                    parent[rb] = ra
                elif rb < ra:
                    parent[ra] = rb
                k += 1
        prev_first = first
    final = np.zeros(n_run, dtype=np.int32)
    sizes = np.zeros(n_run, dtype=np.int64)
    boxes = np.empty((n_run, 4), dtype=np.int64)
    n_lab = 0
    for r in range(n_run):
        root = _root(parent, r)
        k = final[root]
        if k == 0:
            n_lab += 1
            k = n_lab
            final[root] = k
            boxes[k - 1, 0] = run_line[r]
            boxes[k - 1, 2] = run_start[r]
            boxes[k - 1, 3] = run_stop[r]
        i = run_line[r]
        for j in range(run_start[r], run_stop[r]):
            lab[i, j] = k
        sizes[k - 1] += run_stop[r] - run_start[r]
        boxes[k - 1, 1] = i + 1
        boxes[k - 1, 2] = min(boxes[k - 1, 2], run_start[r])
        boxes[k - 1, 3] = max(boxes[k - 1, 3], run_stop[r])
    return lab, sizes[:n_lab].copy(), boxes[:n_lab].copy()


@jit(inline="always")
def _rank_in_counts(counts: np.ndarray, k: int) -> int:
    """Index of the value of rank ``k`` (0-based) in the histogram ``counts``."""
    seen = 0
    for i in range(counts.size):
        seen += counts[i]
        if seen > k:
            return i
    return counts.size - 1


@jit()
def integer_median_mad(d: np.ndarray):
    """``median(d)`` and ``median(|d - median(d)|)`` of float32 ``d`` holding small integers, by counting (:func:`ballscan.measure.detection._global_noise`).

    Returns ``(ok, med, mad)``; ``ok`` is False (and the values 0) unless
    every value is an integer and their range is at most ``2 d.size +
    1024``.  Then both medians are exact in float32 (integers and half or
    quarter integers below 2**21), so they are the values of the numpy
    form: the middle order statistic, or the mean of the two middle ones
    in float32.
    """
    n = d.size
    zero = np.float32(0.0)
    two = np.float32(2.0)
    if n == 0:
        return False, zero, zero
    iv = np.empty(n, dtype=np.int32)
    bad = False
    for q in range(n):
        v = d[q]
        bad |= not abs(v) <= np.float32(1048576.0)
        iv[q] = np.int32(v) if abs(v) <= np.float32(1048576.0) else 0
        bad |= np.float32(iv[q]) != v
    if bad:
        return False, zero, zero
    lo = iv.min()
    span = int(iv.max()) - int(lo) + 1
    if span > 2 * n + 1024:
        return False, zero, zero
    base = int(lo)
    counts = np.zeros(span, dtype=np.int64)
    for q in range(n):
        counts[iv[q] - base] += 1
    h = n // 2
    med = np.float32(_rank_in_counts(counts, h) + base)
    if n % 2 == 0:
        med = (np.float32(_rank_in_counts(counts, h - 1) + base) + med) / two
    # |v - med| doubled is an integer: count it
    dev = np.zeros(2 * span + 2, dtype=np.int64)
    for i in range(span):
        if counts[i]:
            dev[int(abs(2.0 * (np.float64(i + base) - np.float64(med))))] += counts[i]
    mad = np.float32(_rank_in_counts(dev, h)) / two
    if n % 2 == 0:
        mad = (np.float32(_rank_in_counts(dev, h - 1)) / two + mad) / two
    return True, med, mad


@jit()
def reflect_median_filter(x: np.ndarray, size: int) -> np.ndarray:
    """``scipy.ndimage.median_filter(x, size, mode="reflect")`` of a 1-D float64 ``x`` without NaN, ``size`` odd and below ``2 x.size`` (:func:`ballscan.measure.detection._background`).

    The windows hold the entries of ``x`` (mirrored at the ends, once, as
    ``d c b a | a b c d | d c b a``) with multiplicities 0 to 2; they are
    kept as counts over ``x`` sorted, and the middle rank is followed as
    the window slides by one (a few steps each), instead of a selection
    per window.
    """
    w = x.size
    r = size // 2
    order = np.argsort(x)
    pos = np.empty(w, dtype=np.int64)
    for q in range(w):
        pos[order[q]] = q
    cnt = np.zeros(w, dtype=np.int64)
    for t in range(-r, r + 1):
        cnt[pos[-t - 1 if t < 0 else (2 * w - 1 - t if t >= w else t)]] += 1
    # p: the sorted position holding rank r of the window; below: the window's entries before it
    p = 0
    below = 0
    while below + cnt[p] <= r:
        below += cnt[p]
        p += 1
    out = np.empty(w)
    out[0] = x[order[p]]
    for i in range(1, w):
        t_out = i - r - 1
        t_in = i + r
        a = pos[-t_out - 1 if t_out < 0 else (2 * w - 1 - t_out if t_out >= w else t_out)]
        b = pos[-t_in - 1 if t_in < 0 else (2 * w - 1 - t_in if t_in >= w else t_in)]
        cnt[a] -= 1
        if a < p:
            below -= 1
        cnt[b] += 1
        if b < p:
            below += 1
        while below > r:
            p -= 1
            below -= cnt[p]
        while below + cnt[p] <= r:
            below += cnt[p]
            p += 1
        out[i] = x[order[p]]
    return out


# error_model="numpy": no zero-division check (the divisors are positive),
# so the divisions vectorise (23 us on a stream crop, against 40 us with
# the check)
@jit(error_model="numpy")
def first_pass_lines(xs: np.ndarray, gain0: np.ndarray, offset0: np.ndarray, bs: np.ndarray, thr: np.ndarray, use_gain: bool):
    """Each line's drift samples with the first-pass ball pixels set to +inf, and their number per line (:func:`ballscan.measure.detection._background`).

    With ``use_gain`` a sample is ``xs / bs`` (``bs`` <= 0: excluded, divided
    by 1) and a pixel is excluded where ``|xs - gain0 bs| > thr``; else it
    is ``xs - bs``, excluded where ``|xs - bs - offset0| > thr``.  The same
    float64 operations as the numpy form (``xs`` float32, widened).
    """
    n, w = xs.shape
    s = np.empty((n, w))
    excluded = np.zeros(n, dtype=np.int64)
    safe = np.empty(w)
    for j in range(w):
        safe[j] = bs[j] if bs[j] > 0 else 1.0
    # one line at a time, in loops without branches (the compiler vectorises them)
    x = np.empty(w)
    for i in range(n):
        row = s[i]
        for j in range(w):
            x[j] = xs[i, j]
        e = 0
        if use_gain:
            g = gain0[i]
            for j in range(w):
                row[j] = x[j] / safe[j]
            for j in range(w):
                out = (abs(x[j] - g * bs[j]) > thr[j]) | (bs[j] <= 0)
                row[j] = np.inf if out else row[j]
                e += out
        else:
            o = offset0[i]
            for j in range(w):
                v = x[j] - bs[j]
                out = abs(v - o) > thr[j]
                row[j] = np.inf if out else v
                e += out
        excluded[i] = e
    return s, excluded


@jit()
def kept_median(s: np.ndarray, excluded: np.ndarray, big: float):
    """Per row of the row-sorted ``s`` (excluded values +inf, ``excluded`` of them): the masked median and the kept count (:func:`ballscan.measure.detection._masked_median`)."""
    n_row, n = s.shape
    med = np.zeros(n_row)
    count = n - excluded
    h = n // 2
    for i in range(n_row):
        if count[i] <= 0:
            continue
        n_low = excluded[i] // 2
        # ranks of the virtual row: n_low values -big, the kept ones, then +big
        hi = h - n_low
        v_hi = -big if hi < 0 else (big if hi >= count[i] else s[i, hi])
        if n % 2:
            med[i] = v_hi
        else:
            lo = hi - 1
            v_lo = -big if lo < 0 else (big if lo >= count[i] else s[i, lo])
            med[i] = (v_lo + v_hi) / 2
    return med, count


@jit()
def fill_lines_and_cols(m: np.ndarray) -> np.ndarray:
    """Union of the per-line and per-column hole fills of the bool mask ``m`` (:func:`ballscan.measure.detection.detect`).

    One sweep along the lines fills each line and finds each column's
    first and last pixel; a second fills the columns (line by line, in
    memory order).
    """
    h, w = m.shape
    out = np.zeros((h, w), dtype=np.bool_)
    first = np.full(w, h)
    last = np.full(w, -1)
    for i in range(h):
        a = -1
        b = -1
        for j in range(w):
            if m[i, j]:
                if a < 0:
                    a = j
                b = j
                first[j] = min(first[j], i)
                last[j] = i
        for j in range(a if a >= 0 else w, b + 1):
            out[i, j] = True
    for i in range(h):
        for j in range(w):
            out[i, j] |= (first[j] <= i) & (i <= last[j])
    return out


@jit()
def group_mask(lab: np.ndarray, l0: int, l1: int, c0: int, c1: int, in_group: np.ndarray) -> np.ndarray:
    """``in_group[lab[l0:l1, c0:c1]]``: the pixels of a group of labels in its box (:func:`ballscan.measure.detection.detect`)."""
    out = np.empty((l1 - l0, c1 - c0), dtype=np.bool_)
    for i in range(l1 - l0):
        for j in range(c1 - c0):
            out[i, j] = in_group[lab[l0 + i, c0 + j]]
    return out


@jit()
def multi_runs(m: np.ndarray, axis: int):
    """Lines (``axis=1``) or columns (``axis=0``) of the bool mask ``m`` in two or more runs of True: those with such a neighbour, and the others (:func:`ballscan.measure.detection._merged_runs`)."""
    h, w = m.shape
    if axis == 1:
        runs = np.zeros(h, dtype=np.int64)
        for i in range(h):
            for j in range(w):
                runs[i] += m[i, j] and (j == 0 or not m[i, j - 1])
    else:
        runs = np.zeros(w, dtype=np.int64)
        for j in range(w):
            runs[j] += m[0, j]
        for i in range(1, h):
            for j in range(w):
                runs[j] += m[i, j] and not m[i - 1, j]
    size = runs.size
    paired = np.zeros(size, dtype=np.bool_)
    lone = np.zeros(size, dtype=np.bool_)
    for k in range(size):
        if runs[k] >= 2:
            if (k > 0 and runs[k - 1] >= 2) or (k + 1 < size and runs[k + 1] >= 2):
                paired[k] = True
            else:
                lone[k] = True
    return paired, lone


@jit()
def region_values(x: np.ndarray, gain: np.ndarray, b: np.ndarray, offset: np.ndarray, l0: int, c0: int, mask: np.ndarray, sat: float):
    """Ball-minus-background values of the mask's pixels (in raster order) and whether any is at or above ``sat`` (:func:`ballscan.measure.detection.detect`).

    The box's background is ``gain * b + offset`` as in
    :func:`ballscan.measure.detection.background_at` (the same float64 operations).
    """
    h, w = mask.shape
    vals = np.empty(h * w)
    k = 0
    saturated = False
    for i in range(h):
        for j in range(w):
            if mask[i, j]:
                xv = x[l0 + i, c0 + j]
                vals[k] = xv - (gain[l0 + i] * b[c0 + j] + offset[l0 + i])
                saturated = saturated or xv >= sat
                k += 1
    return vals[:k].copy(), saturated


def warm_up() -> None:
    """Load (or compile) this module's kernels now, on tiny inputs (see :func:`ballscan.pipeline.warmup.warm_up`)."""
    mode_seek(np.zeros((1, 2), dtype=np.float32), np.zeros(1), np.ones(1), 0.5)
    one32 = np.ones(2, dtype=np.float32)
    label_hits(np.ones((2, 2), dtype=np.float32), one32, one32, one32, one32)
    integer_median_mad(np.zeros(2, dtype=np.float32))
    reflect_median_filter(np.zeros(3), 3)
    s, e = first_pass_lines(np.ones((1, 2), dtype=np.float32), np.ones(1), np.zeros(1), np.ones(2), np.ones(2), True)
    kept_median(s, e, 1e300)
    multi_runs(group_mask(np.zeros((2, 2), dtype=np.int32), 0, 2, 0, 2, np.ones(1, dtype=np.bool_)), 1)
    region_values(np.ones((2, 2)), np.ones(2), np.ones(2), np.zeros(2), 0, 0, fill_lines_and_cols(np.ones((2, 2), dtype=np.bool_)), 255.0)
    second_level(np.zeros((1, 4), dtype=np.float32), np.zeros(1), np.ones(1))
    pair_offs(np.ones((2, 2)), np.zeros((2, 2), dtype=np.bool_), np.ones(2), np.ones(2), True, 1, False)
    scale_counts(np.ones((1, 2)), np.ones(2), np.ones(2), np.ones(2), True, 255.0)
    on_first(np.ones((1, 2), dtype=np.float32), np.ones(1), np.ones(2), np.ones(2), True, 255.0)
