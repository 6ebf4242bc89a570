"""The stream engine's kernels (ballscan.stream._line_kernels) against the engine's numpy forms, and their one compiled signature each."""

from __future__ import annotations

import numpy as np

from ballscan.geometry.camera import LineScanCamera
from ballscan.stream import _line_kernels as K


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
