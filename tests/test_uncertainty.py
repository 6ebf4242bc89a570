"""The fit's covariance: parameters that a full-rank fit still does not fix (solve.uncertainty.unfixed_parameters)."""

from __future__ import annotations

import numpy as np
import pytest

from ballscan.geometry.motion import BallMotion
from ballscan.solve.uncertainty import MAX_VELOCITY_SIGMA_RATIO, unfixed_parameters

#: the scales' motion (e.g. the key-point guess): 2 m away, 10 m/s across the plane and 1 m/s along the sensor
GUESS = BallMotion(0.0335, 1e-3, (0.0, 0.05, 2.0), (10.0, 1.0, 0.0))
NAMES = ("t_c_s", "y0_m", "z0_m", "vx_mps", "vy_mps", "vz_mps")
SMALL = [1e-6, 1e-4, 1e-2, 0.1, 0.1, 2.0]


def _cov(sigmas):
    return np.diag(np.square(sigmas))


def test_small_sigmas_fix_every_parameter():
    assert unfixed_parameters(_cov(SMALL), GUESS) == ()


@pytest.mark.parametrize(
    "k,limit",
    [
        (0, 2 * 0.0335 / 10.0),  # t_c: the time the ball takes to cross the plane
        (1, 2.0),  # y0, z0: the distance
        (2, 2.0),
        (3, MAX_VELOCITY_SIGMA_RATIO * np.hypot(10.0, 1.0)),  # a velocity component: the speed across the plane
        (5, MAX_VELOCITY_SIGMA_RATIO * np.hypot(10.0, 1.0)),
    ],
)
def test_a_sigma_beyond_its_scale_leaves_that_parameter_unfixed(k, limit):
    sig = np.array(SMALL)
    sig[k] = 0.99 * limit
    assert unfixed_parameters(_cov(sig), GUESS) == ()
    sig[k] = 1.01 * limit
    assert unfixed_parameters(_cov(sig), GUESS) == (NAMES[k],)


def test_the_scales_are_the_given_motions_not_the_fits():
    """A fit that wandered to a large V.y along a weak direction does not widen V.z's scale: the guess sets it."""
    sig = np.array(SMALL)
    sig[5] = 40.0  # 4x the guess's 10 m/s across the plane
    assert unfixed_parameters(_cov(sig), GUESS) == ("vz_mps",)
    fast = BallMotion(0.0335, 1e-3, (0.0, 0.05, 2.0), (10.0, 15.0, 0.0))
    assert unfixed_parameters(_cov(sig), fast) == ()


def test_nan_rows_count_as_unfixed():
    cov = _cov(SMALL)
    cov[4, :] = cov[:, 4] = np.nan
    assert unfixed_parameters(cov, GUESS) == ("vy_mps",)
