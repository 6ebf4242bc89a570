"""A Gaussian prior on one motion parameter or velocity component (ballscan.solve.prior): its residual and Jacobian row, its pull on the fit, its share in the covariance."""

from __future__ import annotations

import math

import numpy as np
import pytest

from ballscan.geometry.camera import LineScanCamera
from ballscan.geometry.motion import BallMotion
from ballscan.solve.fit import fit_motion
from ballscan.solve.prior import ParameterPrior, VelocityPrior, WithPrior
from ballscan.solve.synthetic import synthetic_edges

CAM = LineScanCamera(2048, 4200.0, 1023.5, 70000.0, 1.2e-5)
TRUTH = BallMotion(0.0335, 0.0017, (0, -0.08, 4.2), (44.5, 3.9, -5.5))


@pytest.mark.parametrize(
    "kw, word",
    [(dict(name="vw_mps", mean=0.0, sigma=1.0), "name"), (dict(name="vz_mps", mean=math.nan, sigma=1.0), "mean"),
     (dict(name="vz_mps", mean=0.0, sigma=0.0), "sigma"), (dict(name="vz_mps", mean=0.0, sigma=math.inf), "sigma"),
     (dict(name="vz_mps", mean=True, sigma=1.0), "mean")],
)  # fmt: skip
def test_a_prior_is_checked_at_construction(kw, word):
    with pytest.raises(ValueError, match=f"ParameterPrior.{word}"):
        ParameterPrior(**kw)


def test_numpy_numbers_make_a_prior():
    assert ParameterPrior("vz_mps", np.float32(1.5), np.int64(2)).index == 5


@pytest.mark.parametrize(
    "kw, word",
    [(dict(direction=(0.0, 0.0, 0.0), mean=0.0, sigma=1.0), "direction"), (dict(direction=(0.0, 1.0), mean=0.0, sigma=1.0), "direction"),
     (dict(direction=(0.0, np.nan, 1.0), mean=0.0, sigma=1.0), "direction"), (dict(direction=(0.0, 0.0, 1.0), mean=math.inf, sigma=1.0), "mean"),
     (dict(direction=(0.0, 0.0, 1.0), mean=0.0, sigma=-1.0), "sigma")],
)  # fmt: skip
def test_a_velocity_prior_is_checked_at_construction(kw, word):
    with pytest.raises(ValueError, match=f"VelocityPrior.{word}"):
        VelocityPrior(**kw)


def test_a_velocity_prior_along_z_is_the_prior_on_vz():
    rng = np.random.default_rng(5)
    inner = _Linear(rng.normal(size=(9, 7)), rng.normal(size=9))
    inner.fit_bias = True
    x = rng.normal(size=7)
    along = WithPrior(inner, VelocityPrior((0.0, 0.0, 2.0), 0.3, 0.5)).residuals_and_jacobian(x)
    on = WithPrior(inner, ParameterPrior("vz_mps", 0.3, 0.5)).residuals_and_jacobian(x)
    np.testing.assert_array_equal(along[0], on[0])
    np.testing.assert_array_equal(along[1], on[1])


class _Linear:
    """``r = A x - b``: a problem whose Jacobian is known."""

    fit_bias = False

    def __init__(self, A, b):
        self.A, self.b = A, b

    def residuals(self, x):
        return self.A @ x - self.b

    def residuals_and_jacobian(self, x):
        return self.residuals(x), self.A.copy()

    def start(self):
        return None, self.A.copy()


def test_the_prior_is_one_more_residual_with_its_jacobian_row():
    rng = np.random.default_rng(3)
    inner = _Linear(rng.normal(size=(9, 6)), rng.normal(size=9))
    p = WithPrior(inner, ParameterPrior("vz_mps", 2.0, 0.5))
    x = rng.normal(size=6)
    r, J = p.residuals_and_jacobian(x)
    np.testing.assert_array_equal(r[:9], inner.residuals(x))
    assert r[9] == pytest.approx((x[5] - 2.0) / 0.5)
    h = 1e-6
    fd = np.array([(p.residuals(x + h * e) - p.residuals(x - h * e)) / (2 * h) for e in np.eye(6)]).T
    np.testing.assert_allclose(J, fd, atol=1e-8)
    np.testing.assert_array_equal(p.start()[1], J)


def test_a_tight_prior_pins_its_parameter_and_its_sigma():
    e = synthetic_edges(CAM, TRUTH, 240, edge_sigma_px=0.02, seed=0)
    start = BallMotion(TRUTH.radius_m, TRUTH.t_c_s, (0, -0.079, 4.25), (44.0, 3.8, -4.0))
    free = fit_motion(CAM, e, start)
    pinned = fit_motion(CAM, e, start, prior=ParameterPrior("vz_mps", 0.0, 1e-4))
    assert abs(pinned.motion.velocity_mps[2]) < 1e-3
    assert math.sqrt(pinned.covariance[5, 5]) < 1.1e-4
    # the edges see vz = -5.5 m/s: held at 0 against them, the fit's residuals grow
    assert abs(free.motion.velocity_mps[2] - TRUTH.velocity_mps[2]) < 3 * math.sqrt(free.covariance[5, 5])
    assert pinned.chi2_red > free.chi2_red


def test_a_tight_velocity_prior_pins_its_component_and_leaves_the_one_across_it_free():
    e = synthetic_edges(CAM, TRUTH, 240, edge_sigma_px=0.02, seed=0)
    start = BallMotion(TRUTH.radius_m, TRUTH.t_c_s, (0, -0.079, 4.25), (44.0, 3.8, -4.0))
    d = np.array([0.0, 0.6, 0.8])
    pinned = fit_motion(CAM, e, start, prior=VelocityPrior(tuple(d), 1.0, 1e-4))
    v = np.asarray(pinned.motion.velocity_mps)
    assert abs(v @ d - 1.0) < 1e-3
    assert math.sqrt(d @ pinned.covariance[3:6, 3:6] @ d) < 1.1e-4


def test_a_wide_prior_leaves_a_determined_fit_as_it_was():
    e = synthetic_edges(CAM, TRUTH, 240, edge_sigma_px=0.02, seed=1)
    free = fit_motion(CAM, e, TRUTH)
    wide = fit_motion(CAM, e, TRUTH, prior=ParameterPrior("vz_mps", 0.0, 1e4))
    np.testing.assert_allclose(wide.motion.velocity_mps, free.motion.velocity_mps, rtol=1e-6, atol=1e-6)
    np.testing.assert_allclose(np.sqrt(np.diag(wide.covariance)), np.sqrt(np.diag(free.covariance)), rtol=1e-3)
