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
