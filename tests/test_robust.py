"""Robust statistics (ballscan.measure.robust) against numpy's."""

from __future__ import annotations

import numpy as np
import pytest

from ballscan.measure.robust import MAD_TO_SIGMA, median, weighted_median


def test_median_is_numpys_median():
    rng = np.random.default_rng(1)
    for a in (
        rng.normal(size=101),
        rng.normal(size=(12, 10)).astype(np.float32),
        np.round(rng.normal(size=64) * 4),
        rng.integers(0, 255, 33).astype(np.uint8),
        np.array([2.0, np.nan, 1.0]),
        # the compiled selection: even sizes, many ties, views, other dtypes
        rng.normal(size=5336).astype(np.float32),
        np.round(rng.normal(size=(90, 100)) * 3)[:, ::3],
        rng.integers(-50, 50, 1000),
        rng.normal(size=40).astype(np.float16),
        np.array([np.nan, 1.0, 2.0, 3.0], dtype=np.float32),
    ):
        got, ref = median(a), np.median(a)
        assert type(got) is type(ref)
        assert got == ref or (np.isnan(got) and np.isnan(ref))
    with pytest.raises(ValueError, match="empty"):
        median(np.array([]))


def test_weighted_median_is_the_median_of_the_repeated_values():
    rng = np.random.default_rng(2)
    for trial in range(200):
        v = np.round(rng.normal(size=int(rng.integers(1, 30))) * 3)
        c = rng.integers(0, 5, v.size)
        if c.sum() == 0:
            c[0] = 1
        assert weighted_median(v, c) == float(np.median(np.repeat(v, c))), trial


def test_mad_to_sigma_is_that_of_normal_noise():
    from scipy.stats import norm

    assert MAD_TO_SIGMA == pytest.approx(1.0 / norm.ppf(0.75), rel=1e-15)
