"""Compiled loops of the stream engine: the per-line band test and the block update's sums.

The engine (:mod:`ballscan.stream.engine`) tests every line of the stream
(2048-pixel lines at >= 140 000 lines/s, benchmarks/bench_stream.py), and a
ball's result waits for the test of the lines up to its event's end.  As
numpy expressions the test of a block of lines is some twenty whole-array
passes (a wrapped difference, a comparison, the per-line offsets' gather
and sort, the run rule on the candidate lines); one pass per line over the
stored values does the same with 8- or 16-bit lanes.  Each kernel exists
for uint8 and for uint16 lines (one signature each); the bodies are shared.
"""

from __future__ import annotations

import numpy as np

from ..compiled import jit, select_kth


@jit(inline="always")
def _max_excess(row: np.ndarray, lo: np.ndarray, span: np.ndarray, o: int) -> int:
    """Largest ``((x - lo - o) mod 2^b) - span`` over ``row``, or 0 (no pixel outside the band); ``b`` the bits of the values (uint8: 8, uint16: 16)."""
    # every operation in the values' own uint8 / uint16 lanes (the wrap is
    # the modulo; the cast of o keeps its low b bits) and over the whole
    # row: LLVM vectorises this loop (~0.1 ns a pixel), which it did not on
    # int32 / int64 values or over 64-pixel blocks (~3 ns a pixel)
    lane = row.dtype.type
    ob = lane(o)
    mx = lane(0)
    for j in range(row.shape[0]):
        d = lane(lane(row[j] - lo[j]) - ob)
        e = lane(d - span[j]) if d > span[j] else lane(0)
        mx = max(mx, e)
    return np.int64(mx)


@jit(inline="always")
def _outside(row: np.ndarray, lo: np.ndarray, span: np.ndarray, o: int, out: np.ndarray) -> None:
    """``out[j] = (x[j] - lo[j] - o) mod 2^b > span[j]`` (1 or 0), vectorised as :func:`_max_excess`."""
    lane = row.dtype.type
    ob = lane(o)
    for j in range(row.shape[0]):
        d = lane(lane(row[j] - lo[j]) - ob)
        out[j] = np.uint8(1) if d > span[j] else np.uint8(0)


@jit(inline="always")
def _kth_in_window(hist: np.ndarray, T: int, neg: int, k: int) -> int:
    """The ``k``-th smallest value (0-based), known to lie in ``[-T, T]``, of the values histogrammed in ``hist`` (bin ``v + T``); ``neg`` values are negative.

    Walks from 0 (where a line's offset usually is: a few steps) instead of
    summing the histogram from ``-T``.
    """
    if k < neg:
        # C(t) = values <= t; C(-1) = neg > k: the smallest t with C(t) > k is below 0
        t = -1
        c = neg
        while c - hist[t + T] > k:
            c -= hist[t + T]
            t -= 1
        return t
    t = 0
    c = neg + hist[T]
    while c <= k:
        t += 1
        c += hist[t + T]
    return t


@jit(inline="always")
def _line_offset(row: np.ndarray, ocols: np.ndarray, bg16: np.ndarray, max_off: int, buf: np.ndarray, hist: np.ndarray, T: int) -> int:
    """Offset (whole DN) of ``row`` from the background: ``clip(rint(median(16 x - bg16) / 16), -max_off, max_off)``.

    ``16 x - bg16`` over the columns ``ocols`` (fixed point, 4 fractional
    bits), the median the mean of the middle one or two values.  When both
    middle values lie in the window ``|v| <= T = 16 (max_off + 1)`` they are
    read off a histogram of the window (``hist``: ``2 T + 1`` zeros, left
    zeroed, or empty: then by selection); when both lie beyond one side
    the clipped offset is known (``+-max_off``); otherwise (a ball over
    about half the sampled columns) by selection.  The same value in every
    case: a histogram's cumulative count costs ~2 T steps against ~200
    unpredictable branches of a selection among 64 values.
    """
    m = ocols.shape[0]
    ka = (m - 1) // 2
    kb = m // 2
    below = 0
    above = 0
    neg = 0
    for c in range(m):
        v = (np.int64(row[ocols[c]]) << 4) - bg16[c]
        buf[c] = v
        # counts without branches (their outcomes are unpredictable)
        neg += v < 0
        below += v < -T
        above += v > T
    if kb < below:
        return -max_off  # (a + b) / 32 < -(max_off + 1)
    if ka >= m - above:
        return max_off
    if hist.shape[0] > 0 and ka >= below and kb < m - above:
        for c in range(m):
            v = buf[c]
            if -T <= v <= T:
                hist[v + T] += 1
        a = _kth_in_window(hist, T, neg, ka)
        b = a if kb == ka else _kth_in_window(hist, T, neg, kb)
        for c in range(m):
            v = buf[c]
            if -T <= v <= T:
                hist[v + T] = 0
    else:
        a = select_kth(buf, m, ka)
        b = a
        if kb != ka:
            # the smallest of the values above the ka-th
            b = buf[kb]
            for c in range(kb + 1, m):
                b = min(b, buf[c])
    v = np.rint((np.float64(a) + np.float64(b)) / 32.0)
    return np.int64(min(max(v, -np.float64(max_off)), np.float64(max_off)))


@jit(inline="always")
def _band_test(ring, first, n, lo, span, ocols, bg16, max_off, min_run, offsets, off_ring, hit_ring):
    """The body of :func:`stream_line_test_u8` / ``_u16`` (see there)."""
    cap, w = ring.shape
    m = ocols.shape[0]
    buf = np.empty(m, dtype=np.int64)
    T = 16 * (max_off + 1)
    # a histogram of more than ~1000 bins (16-bit data's wide bands) costs
    # more than selection
    hist = np.zeros(2 * T + 1 if T <= 512 else 0, dtype=np.int64)
    flags = np.empty(w, dtype=np.uint8)
    idx = np.empty(n, dtype=np.int64)
    cnt = np.empty(n, dtype=np.int64)
    cmin = np.empty(n, dtype=np.int64)
    cmax = np.empty(n, dtype=np.int64)
    k = 0
    for i in range(n):
        r = (first + i) % cap
        row = ring[r]
        o = _line_offset(row, ocols, bg16, max_off, buf, hist, T) if offsets else 0
        off_ring[r] = o
        # first pass, vectorised: does the line hold an outside pixel at all
        # (most lines hold none; ~13 % of 2048-pixel lines one by chance)
        e = _max_excess(row, lo, span, o)
        hit = False
        if e > 0:
            # the outside flags (vectorised), then the run rule over them
            _outside(row, lo, span, o, flags)
            run = 0
            count = 0
            j_first = -1
            j_last = -1
            for j in range(w):
                if flags[j]:
                    run += 1
                    if run >= min_run:
                        count += 1
                        if j_first < 0:
                            j_first = j - min_run + 1
                        j_last = j
                else:
                    run = 0
            if count > 0:
                hit = True
                idx[k] = i
                cnt[k] = count
                cmin[k] = j_first
                cmax[k] = j_last
                k += 1
        hit_ring[r] = hit
    return idx[:k], cnt[:k], cmin[:k], cmax[:k]


@jit()
def stream_line_test_u8(
    ring: np.ndarray,
    first: int,
    n: int,
    lo: np.ndarray,
    span: np.ndarray,
    ocols: np.ndarray,
    bg16: np.ndarray,
    max_off: int,
    min_run: int,
    offsets: bool,
    off_ring: np.ndarray,
    hit_ring: np.ndarray,
):
    """The stream engine's per-line test of ring rows ``first, first + 1, ...`` (``n`` rows, modulo the ring's length).

    Parameters
    ----------
    ring : numpy.ndarray
        uint8 (cap, W): stored values (DN).
    lo, span : numpy.ndarray
        uint8 (W,): the band ``[lo, lo + span]`` of each column (DN).
    ocols : numpy.ndarray
        int64: the columns of the per-line offset.
    bg16 : numpy.ndarray
        int64: ``rint(16 * background)`` at ``ocols`` (1/16 DN).
    max_off : int
        Clip of the per-line offset (whole DN).
    min_run : int
        Adjacent outside pixels that make a hit line.
    offsets : bool
        Shift each line's band by its offset (else offset 0).
    off_ring : numpy.ndarray
        int32 (cap,): receives each tested row's offset (DN).
    hit_ring : numpy.ndarray
        bool (cap,): receives whether each tested row is a hit line.

    Returns
    -------
    tuple of numpy.ndarray
        int64, one value per hit line: its index among the ``n`` rows, the
        number of run positions (pixels ``j`` starting ``min_run`` outside
        pixels), the first such ``j`` and the last one plus ``min_run - 1``
        (the numpy form's ``counts``, ``cmin``, ``cmax``). A pixel is outside
        when ``(x - lo - o) mod 256 > span`` (``o`` the line's offset).
    """
    return _band_test(ring, first, n, lo, span, ocols, bg16, max_off, min_run, offsets, off_ring, hit_ring)


@jit()
def stream_line_test_u16(
    ring: np.ndarray,
    first: int,
    n: int,
    lo: np.ndarray,
    span: np.ndarray,
    ocols: np.ndarray,
    bg16: np.ndarray,
    max_off: int,
    min_run: int,
    offsets: bool,
    off_ring: np.ndarray,
    hit_ring: np.ndarray,
):
    """:func:`stream_line_test_u8` for uint16 ``ring``, ``lo`` and ``span`` (modulo 65536)."""
    return _band_test(ring, first, n, lo, span, ocols, bg16, max_off, min_run, offsets, off_ring, hit_ring)


@jit(inline="always")
def _block_sums(ring, off_ring, rows):
    """The body of :func:`stream_block_sums_u8` / ``_u16``."""
    w = ring.shape[1]
    t1 = np.zeros(w, dtype=np.int64)
    t2 = np.zeros(w, dtype=np.int64)
    for q in range(rows.shape[0]):
        r = rows[q]
        o = np.int64(off_ring[r])
        row = ring[r]
        for j in range(w):
            v = np.int64(row[j]) - o
            t1[j] += v
            t2[j] += v * v
    return t1.astype(np.float64), t2.astype(np.float64)


@jit()
def stream_block_sums_u8(ring: np.ndarray, off_ring: np.ndarray, rows: np.ndarray):
    """Per-column sums of ``x - o`` and of ``(x - o)**2`` over the ring rows ``rows`` (``o`` each row's offset).

    Parameters
    ----------
    ring : numpy.ndarray
        uint8 (cap, W): stored values (DN).
    off_ring : numpy.ndarray
        int32 (cap,): per-row offsets (DN).
    rows : numpy.ndarray
        int64: the rows summed.

    Returns
    -------
    tuple of numpy.ndarray
        float64 (W,) each (DN, DN^2): exact (integer sums, below 2**53).
    """
    return _block_sums(ring, off_ring, rows)


@jit()
def stream_block_sums_u16(ring: np.ndarray, off_ring: np.ndarray, rows: np.ndarray):
    """:func:`stream_block_sums_u8` for a uint16 ``ring``."""
    return _block_sums(ring, off_ring, rows)


def warm_up() -> None:
    """Load (or compile) the stream engine's kernels now, on tiny inputs.

    A stream whose estimates run in other processes loads only these
    (the estimator's: :func:`ballscan.pipeline.warmup.warm_up`).
    """
    ocols = np.zeros(1, dtype=np.int64)
    rows = np.zeros(1, dtype=np.int64)
    off = np.zeros(1, dtype=np.int32)
    hit = np.zeros(1, dtype=np.bool_)
    for dt, test, sums in ((np.uint8, stream_line_test_u8, stream_block_sums_u8), (np.uint16, stream_line_test_u16, stream_block_sums_u16)):
        ring = np.zeros((1, 2), dtype=dt)
        band = np.zeros(2, dtype=dt)
        test(ring, 0, 1, band, band, ocols, ocols, 1, 2, True, off, hit)
        sums(ring, off, rows)
