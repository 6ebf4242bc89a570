"""The fit's covariance: parameters that a full-rank fit still does not fix (solve.uncertainty.unfixed_parameters)."""

from __future__ import annotations

import numpy as np
import pytest

from ballscan.solve.uncertainty import MAX_VELOCITY_SIGMA_RATIO, unfixed_parameters

THETA = np.array([1e-3, 0.05, 2.0, 10.0, 1.0, -0.5])  # s, m, m, m/s


def _cov(sigmas):
    return np.diag(np.square(sigmas))


def test_small_sigmas_fix_every_parameter():
    assert unfixed_parameters(THETA, _cov([1e-6, 1e-4, 1e-2, 0.1, 0.1, 2.0]), 0.0335) == ()


@pytest.mark.parametrize(
    "k,limit",
    [
        (0, 2 * 0.0335 / 10.0),  # t_c: the time the ball takes to cross the plane
        (1, 2.0),  # y0, z0: the distance
        (2, 2.0),
        (5, MAX_VELOCITY_SIGMA_RATIO * np.hypot(10.0, 1.0)),  # a velocity component: the speed across the plane
    ],
)
def test_a_sigma_beyond_its_scale_leaves_that_parameter_unfixed(k, limit):
    sig = np.array([1e-6, 1e-4, 1e-2, 0.1, 0.1, 2.0])
    names = ("t_c_s", "y0_m", "z0_m", "vx_mps", "vy_mps", "vz_mps")
    sig[k] = 0.99 * limit
    assert unfixed_parameters(THETA, _cov(sig), 0.0335) == ()
    sig[k] = 1.01 * limit
    assert unfixed_parameters(THETA, _cov(sig), 0.0335) == (names[k],)


def test_nan_rows_count_as_unfixed():
    cov = _cov([1e-6, 1e-4, 1e-2, 0.1, 0.1, 2.0])
    cov[4, :] = cov[:, 4] = np.nan
    assert unfixed_parameters(THETA, cov, 0.0335) == ("vy_mps",)
