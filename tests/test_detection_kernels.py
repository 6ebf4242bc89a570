"""The detector's kernels (ballscan.measure._detection_kernels) against their numpy forms."""

from __future__ import annotations

import numpy as np

from ballscan.measure import _detection_kernels as K


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


def _random_mask(rng, max_side=60):
    shape = (int(rng.integers(1, max_side)), int(rng.integers(1, max_side)))
    return rng.random(shape) < rng.uniform(0.02, 0.7)


def test_label_hits_equals_the_threshold_then_ndimage_label_bincount_and_find_objects():
    from scipy import ndimage as ndi

    from ballscan.measure._detection_kernels import label_hits

    rng = np.random.default_rng(3)
    for trial in range(300):
        n, w = int(rng.integers(1, 60)), int(rng.integers(1, 60))
        gain = rng.uniform(0.9, 1.1, n).astype(np.float32)
        b = rng.uniform(0.0, 200.0, w).astype(np.float32)
        offset = (rng.normal(0.0, 2.0, n) if trial % 2 else np.zeros(n)).astype(np.float32)
        x = np.round(np.multiply.outer(gain, b) + rng.normal(0.0, 4.0, (n, w))).astype(np.float32)
        x[rng.random((n, w)) < rng.uniform(0.0, 0.6)] += 50.0
        thr = rng.uniform(1.0, 30.0, w).astype(np.float32)
        # the numpy form
        resid = np.multiply.outer(gain, b)
        if trial % 2:
            resid += offset[:, None]
        hit = np.abs(x - resid) > thr[None, :]
        ref, nlab = ndi.label(hit, structure=np.ones((3, 3), dtype=bool))
        lab, sizes, boxes = label_hits(x, gain, b, offset, thr)
        assert lab.dtype == ref.dtype and np.array_equal(lab, ref)
        assert np.array_equal(sizes, np.bincount(ref[hit], minlength=nlab + 1)[1:])
        objs = ndi.find_objects(ref)
        assert boxes.shape == (nlab, 4)
        assert [tuple(q) for q in boxes.tolist()] == [(o[0].start, o[0].stop, o[1].start, o[1].stop) for o in objs]
    # far more runs than the first allocation holds (it grows)
    x = (rng.random((60, 400)) < 0.5).astype(np.float32)
    ref, nlab = ndi.label(x > 0.5, structure=np.ones((3, 3), dtype=bool))
    lab, sizes, _ = label_hits(x, np.ones(60, np.float32), np.zeros(400, np.float32), np.zeros(60, np.float32), np.full(400, 0.5, np.float32))
    assert np.array_equal(lab, ref) and sizes.size == nlab


def _first_pass_numpy(xs, gain0, offset0, bs, thr, use_gain):
    """The numpy form of the first-pass samples and their masked line medians (ballscan.measure.detection._background)."""
    from ballscan.measure.detection import _BIG

    if use_gain:
        resid = np.multiply.outer(gain0, bs)
        np.subtract(xs, resid, out=resid)
        excluded = np.abs(resid, out=resid) > thr[None, :]
        safe = np.where(bs > 0, bs, 1.0)
        excluded |= (bs <= 0)[None, :]
        a = xs / safe[None, :]
    else:
        a = xs - bs[None, :]
        excluded = np.abs(a - offset0[:, None]) > thr[None, :]
    n_row, n = a.shape
    e = np.count_nonzero(excluded, axis=1)
    count = n - e
    s = np.where(excluded, np.inf, a)
    s.sort(axis=1)
    rows = np.arange(n_row)
    n_low = e // 2

    def at(rank):
        k = rank - n_low
        v = s[rows, np.clip(k, 0, n - 1)]
        return np.where(k < 0, -_BIG, np.where(k >= count, _BIG, v))

    h = n // 2
    med = at(h) if n % 2 else (at(h - 1) + at(h)) / 2
    return np.where(count > 0, med, 0.0), count


def test_first_pass_lines_and_masked_median_equal_their_numpy_form():
    from ballscan.measure._detection_kernels import first_pass_lines
    from ballscan.measure.detection import _masked_median

    rng = np.random.default_rng(4)
    for trial in range(200):
        n, w = int(rng.integers(1, 40)), int(rng.integers(1, 40))
        bs = rng.uniform(-5.0, 120.0, w)
        gain0 = rng.uniform(0.9, 1.1, n).astype(np.float32)
        offset0 = rng.normal(0.0, 3.0, n).astype(np.float32)
        xs = np.round(np.multiply.outer(gain0, bs) + rng.normal(0, 2, (n, w)) + 40 * (rng.random((n, w)) < 0.2)).astype(np.float32)
        if trial % 10 == 0:
            xs[rng.integers(0, n), rng.integers(0, w)] = np.nan
        thr = 3.0 * rng.uniform(0.5, 3.0, w)
        for use_gain in (True, False):
            g0 = gain0 if use_gain else np.ones(n)
            o0 = np.zeros(n) if use_gain else offset0
            ref, ref_count = _first_pass_numpy(xs, g0, o0, bs, thr, use_gain)
            s, e = first_pass_lines(xs, g0.astype(np.float64), o0.astype(np.float64), bs, thr, use_gain)
            got, count = _masked_median(s, e)
            assert np.array_equal(count, ref_count)
            assert np.array_equal(got, ref, equal_nan=True)


def _fill_numpy(m):
    """The numpy form of the union of the per-line and per-column hole fills."""
    h, w = m.shape
    out = np.zeros_like(m)
    for axis, length in ((1, w), (0, h)):
        anyv = m.any(axis=axis)
        first = np.argmax(m, axis=axis)
        last = length - 1 - np.argmax(np.flip(m, axis=axis), axis=axis)
        idx = np.arange(length)
        if axis == 1:
            f = (idx[None, :] >= first[:, None]) & (idx[None, :] <= last[:, None]) & anyv[:, None]
        else:
            f = (idx[:, None] >= first[None, :]) & (idx[:, None] <= last[None, :]) & anyv[None, :]
        out |= f
    return out


def test_fill_lines_and_cols_and_region_values_equal_their_numpy_form():
    from ballscan.measure._detection_kernels import fill_lines_and_cols, region_values

    rng = np.random.default_rng(5)
    for _ in range(300):
        m = _random_mask(rng, 30)
        filled = fill_lines_and_cols(m)
        assert np.array_equal(filled, _fill_numpy(m))
        h, w = m.shape
        n, width = h + int(rng.integers(0, 5)), w + int(rng.integers(0, 5))
        l0, c0 = int(rng.integers(0, n - h + 1)), int(rng.integers(0, width - w + 1))
        x = np.round(rng.uniform(0, 260, (n, width)))
        gain, b, offset = rng.uniform(0.9, 1.1, n), rng.uniform(10, 200, width), rng.normal(0, 2, n)
        box = (slice(l0, l0 + h), slice(c0, c0 + w))
        vals, saturated = region_values(x, gain, b, offset, l0, c0, filled, 255.0)
        ref = (x[box] - (gain[box[0], None] * b[None, box[1]] + offset[box[0], None]))[filled]
        assert np.array_equal(vals, ref)
        assert saturated == bool(np.any(x[box][filled] >= 255.0))


def test_integer_median_mad_equals_the_two_selections():
    from ballscan.measure._detection_kernels import integer_median_mad
    from ballscan.measure.detection import median

    rng = np.random.default_rng(6)
    for trial in range(500):
        d = np.round(rng.normal(size=int(rng.integers(1, 400))) * rng.uniform(0.1, 30.0)).astype(np.float32)
        if trial % 5 == 0:
            d[rng.random(d.size) < 0.1] += 200.0  # outliers (balls)
        ok, med, mad = integer_median_mad(d)
        ref_med = median(d)
        assert ok and np.float32(med) == ref_med
        assert np.float32(mad) == median(np.abs(d - ref_med))
    for d in ([1.5, 2.0], [np.nan, 2.0], [np.inf, 2.0], [0.0, 3e7], [-5000.0, 5000.0]):
        assert not integer_median_mad(np.array(d, dtype=np.float32))[0]


def test_reflect_median_filter_equals_ndimage_median_filter():
    from scipy import ndimage as ndi

    from ballscan.measure._detection_kernels import reflect_median_filter

    rng = np.random.default_rng(7)
    for trial in range(500):
        w = int(rng.integers(1, 300))
        x = rng.normal(size=w) if trial % 2 else np.round(rng.normal(size=w) * 2.0)  # ties
        size = 2 * int(rng.integers(0, w)) + 1
        assert np.array_equal(reflect_median_filter(x, size), ndi.median_filter(x, size=size, mode="reflect"))


def test_multi_runs_and_group_mask_equal_their_numpy_form():
    from ballscan.measure._detection_kernels import group_mask, multi_runs

    def paired(multi):
        pair = multi[:-1] & multi[1:]
        out = np.zeros_like(multi)
        out[:-1] |= pair
        out[1:] |= pair
        return out

    rng = np.random.default_rng(8)
    for _ in range(300):
        m = _random_mask(rng)
        for axis in (0, 1):
            starts = m.copy()
            if axis == 1:
                starts[:, 1:] &= ~m[:, :-1]
            else:
                starts[1:] &= ~m[:-1]
            multi = np.count_nonzero(starts, axis=axis) >= 2
            got, lone = multi_runs(m, axis)
            assert np.array_equal(got, paired(multi))
            assert np.array_equal(lone, multi & ~paired(multi))
        lab = rng.integers(0, 6, m.shape).astype(np.int32)
        in_group = rng.random(6) < 0.5
        l0, c0 = int(rng.integers(0, m.shape[0])), int(rng.integers(0, m.shape[1]))
        l1, c1 = int(rng.integers(l0, m.shape[0] + 1)), int(rng.integers(c0, m.shape[1] + 1))
        assert np.array_equal(group_mask(lab, l0, l1, c0, c1, in_group), in_group[lab[l0:l1, c0:c1]])
