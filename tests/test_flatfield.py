"""Column-gain scatter on a ball's interior: against known gains, and where it cannot be measured."""

from __future__ import annotations

import numpy as np
import pytest

from ballscan.measure.flatfield import _column_median_mad, _masked_median, column_gains, flat_fielded


def _disc(n_lines: int, n_cols: int, prnu: float, noise: float, seed: int, shade: float = 0.0):
    """A ball-like disc (ellipse over lines x columns) at 150 DN on 20, per-column gains, Gaussian noise."""
    rng = np.random.default_rng(seed)
    ll, cc = np.meshgrid(np.linspace(-1, 1, n_lines), np.linspace(-1, 1, n_cols), indexing="ij")
    inside = ll**2 + cc**2 < 0.95
    gain = 1.0 + prnu * rng.standard_normal(n_cols)
    # a smooth brightness across the ball (a shaded side) is the ball's, not the sensor's
    level = 150.0 * (1.0 + shade * cc)
    bg = np.full((n_lines, n_cols), 20.0)
    data = bg + np.where(inside, level * gain[None, :], 0.0) + noise * rng.standard_normal((n_lines, n_cols))
    return data, bg, inside, gain


@pytest.mark.parametrize("prnu", [0.0, 0.004, 0.01])
def test_scatter_of_known_gains(prnu):
    est = []
    for seed in range(4):
        data, bg, mask, _ = _disc(300, 120, prnu, 2.0, seed)
        est.append(column_gains(data, bg, mask, 0, 0, +1).prnu_sigma)
    # noise 2 DN on 150: a column's median over ~250 lines has sigma ~0.001
    if prnu == 0:
        assert max(est) < 0.0015, est
    else:
        assert 0.7 * prnu < np.median(est) < 1.3 * prnu, est


def test_smooth_shading_is_neither_taken_for_gains_nor_hides_them():
    data, bg, mask, _ = _disc(300, 120, 0.0, 2.0, 1, shade=0.3)
    assert column_gains(data, bg, mask, 0, 0, +1).prnu_sigma < 0.0015
    # a running median across the columns read 0.0019-0.0043 here
    est = [column_gains(*_disc(300, 120, 0.008, 2.0, seed, shade=0.3)[:3], 0, 0, +1).prnu_sigma for seed in range(4)]
    assert 0.7 * 0.008 < np.median(est) < 1.3 * 0.008, est


def test_dark_ball_and_gains_follow_the_columns():
    data, bg, mask, gain = _disc(300, 120, 0.01, 1.0, 2)
    dark = 2 * bg - data  # the same signal below the background
    g = column_gains(dark, bg, mask, 0, 0, -1)
    have = g.n_lines >= 8
    assert np.corrcoef(g.gain[have], gain[have] / np.median(gain[have]))[0, 1] > 0.8


def test_too_few_lines_or_columns_say_nothing():
    data, bg, mask, _ = _disc(6, 120, 0.01, 1.0, 3)
    g = column_gains(data, bg, mask, 0, 0, +1)
    # not measured is not flat: NaN, never the 0 of a flat-fielded sensor
    assert np.isnan(g.prnu_sigma) and g.n_columns == 0 and np.all(g.gain == 1.0)
    data, bg, mask, _ = _disc(300, 12, 0.01, 1.0, 3)
    assert np.isnan(column_gains(data, bg, mask, 0, 0, +1).prnu_sigma)


def test_gain_sigma_describes_the_remaining_gain_error():
    # the shrunk gains' error about the true ones (relative to their mean):
    # the posterior alone said 0.0013-0.0030 where the quick sweep's balls
    # were 0.0030-0.0049 off (the smooth trend takes 0.15 of a white gain
    # pattern's variance); with that part, z RMS 1.0-1.7 there.  Here
    # (4 seeds) 0.86-1.05, without it 2.3-3.3
    z = []
    for seed in range(4):
        data, bg, mask, gain = _disc(300, 120, 0.008, 2.0, seed)
        g = column_gains(data, bg, mask, 0, 0, +1)
        meas = g.n_lines >= 8
        err = g.gain[meas] - gain[meas] / np.mean(gain[meas])
        z.append(np.sqrt(np.mean((err / g.gain_sigma[meas]) ** 2)))
        # outside the box and where not measured: the gains' spread
        assert np.all(g.residual_sigma(np.array([-5, 500])) == g.prnu_sigma)
    assert 0.6 < np.median(z) < 1.8, z


def test_a_stuck_column_is_no_gain_and_flat_fielding_stays_below_saturation():
    # A column stuck at the background inside the ball reads a ratio of ~0
    # to the trend: taken for a gain it would scale its signal by hundreds
    # (a gain of -0.0045 without this guard).  It keeps gain 1 and its whole
    # deviation as its error; the other columns' gains are untouched.
    data, bg, mask, gain = _disc(300, 120, 0.008, 2.0, 0)
    stuck = 60
    data[:, stuck] = bg[:, stuck]
    g = column_gains(data, bg, mask, 0, 0, +1)
    assert g.gain[stuck] == 1.0 and g.gain_sigma[stuck] > 0.5
    assert np.all((g.gain > 0.9) & (g.gain < 1.1))
    others = np.flatnonzero(g.n_lines >= 20)
    others = others[others != stuck]
    clean = column_gains(_disc(300, 120, 0.008, 2.0, 0)[0], bg, mask, 0, 0, +1)
    assert np.abs(g.gain[others] - clean.gain[others]).max() < 0.1 * 0.008
    # pixels below saturation stay below it after a gain under 1 is divided out
    sat = float(data.max()) + 0.5
    ff = flat_fielded(data, bg, g, slice(0, data.shape[0]), saturation_dn=sat)
    assert np.all(ff[data < sat] < sat) and np.all(np.isfinite(ff))


def _masked_median_numpy(values, mask, axis):
    """The numpy form of ballscan.measure.flatfield._masked_median (one sort, the mask's counts and two gathers)."""
    v = np.sort(np.where(mask, values, np.inf), axis=axis)
    n = mask.sum(axis=axis)
    lo = np.expand_dims(np.maximum((n - 1) // 2, 0), axis)
    hi = np.expand_dims(np.maximum(n // 2, 0), axis)
    med = 0.5 * (np.take_along_axis(v, lo, axis) + np.take_along_axis(v, hi, axis))
    return np.where(n > 0, np.squeeze(med, axis), np.nan)


def test_masked_median_is_the_numpy_forms_bit_for_bit():
    rng = np.random.default_rng(5)
    for trial in range(400):
        a, b = (int(x) for x in rng.integers(1, 25, 2))
        v = rng.standard_normal((a, b))
        if trial % 3 == 0:
            v = np.round(3 * v)  # ties
        if trial % 4 == 0:
            v[rng.random((a, b)) < 0.1] = np.nan
            v[rng.random((a, b)) < 0.1] = np.inf
        mask = rng.random((a, b)) < rng.random()
        for axis in (0, 1):
            with np.errstate(invalid="ignore"):
                want = _masked_median_numpy(v, mask, axis)
            assert np.array_equal(_masked_median(v, mask, axis), want, equal_nan=True), (trial, axis)


def test_column_median_and_deviation_are_the_numpy_forms_bit_for_bit():
    rng = np.random.default_rng(6)
    for trial in range(600):
        a, b = (int(x) for x in rng.integers(1, 40, 2))
        v = rng.standard_normal((a, b)) * 10.0 ** rng.uniform(-3, 3)
        if trial % 3 == 0:
            v = np.round(3 * v) / 3  # ties
        if trial % 5 == 0:
            # not finite: the deviations sorted as they are
            v[rng.random((a, b)) < 0.05] = np.nan
            v[rng.random((a, b)) < 0.05] = -np.inf
        mask = rng.random((a, b)) < rng.random()
        with np.errstate(invalid="ignore"):
            med = _masked_median_numpy(v, mask, 0)
            mad = _masked_median_numpy(np.abs(v - med[None, :]), mask, 0)
            got = _column_median_mad(v, mask)
        assert np.array_equal(got[0], med, equal_nan=True) and np.array_equal(got[1], mad, equal_nan=True), trial


def test_the_trend_is_scipys_savitzky_golay_filter():
    from scipy.signal import savgol_coeffs, savgol_filter

    from ballscan.measure.flatfield import _TREND_COLS, _trend, _trend_filter

    coef, _, leak = _trend_filter()
    np.testing.assert_allclose(coef, savgol_coeffs(_TREND_COLS, 2), rtol=0, atol=1e-14)
    assert leak == pytest.approx(float(np.sum(coef**2)))
    x = np.random.default_rng(1).normal(size=80).cumsum()
    np.testing.assert_allclose(_trend(x.copy()), savgol_filter(x, _TREND_COLS, 2, mode="interp"), rtol=0, atol=1e-9)


def test_the_symmetric_filter_is_scipys_convolve1d_bit_for_bit():
    from scipy.ndimage import convolve1d

    from ballscan.measure.flatfield import _symmetric_filter, _trend_filter

    rng = np.random.default_rng(7)
    coefs = [_trend_filter()[0]]
    for m in (0, 1, 3, 9):
        half = rng.normal(size=m + 1)
        coefs.append(np.concatenate([half, half[-2::-1]]))  # symmetric, odd length
    for coef in coefs:
        for n in (1, 2, 7, 15, 16, 120, 2048):
            for scale in (1e-3, 1.0, 255.0, 1e6):
                x = scale * rng.standard_normal(n) + scale * rng.uniform(-3, 3)
                got = _symmetric_filter(x, coef)
                assert np.array_equal(got, convolve1d(x, coef, mode="constant")), (coef.size, n, scale)
