"""The fit's covariance: parameters that a full-rank fit still does not fix (solve.uncertainty.unfixed_parameters, unfixed_across_sight), and the speed's components (significant_square)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from ballscan.geometry.motion import BallMotion
from ballscan.solve.uncertainty import MAX_VELOCITY_SIGMA_RATIO, sight_axes, unfixed_across_sight, unfixed_parameters

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


@pytest.mark.parametrize("y0", [-2.5, -0.4, 0.0, 0.3, 3.0])
def test_the_line_of_sights_axes_are_orthonormal_in_the_viewing_plane(y0):
    across, along = sight_axes((0.0, y0, 5.0))
    np.testing.assert_allclose([across @ across, along @ along, across @ along], [1.0, 1.0, 0.0], atol=1e-15)
    np.testing.assert_allclose(along * np.hypot(y0, 5.0), [0.0, y0, 5.0], rtol=1e-14)
    assert across[0] == along[0] == 0.0 and across[1] > 0.0


@pytest.mark.parametrize("y0", [-1.2, 0.8])
def test_off_the_axis_a_flat_direction_along_the_line_of_sight_leaves_vy_and_vz_unfixed_and_the_velocity_across_it_fixed(y0):
    """The weak direction along the sight line has parts in vy and vz: both exceed their scale, vx and v_across do not."""
    centre = (0.0, y0, 2.0)
    across, along = sight_axes(centre)
    C = _cov(SMALL)
    C[3:6, 3:6] += 100.0**2 * np.outer(along, along)
    guess = BallMotion(0.0335, 1e-3, centre, (10.0, 1.0, 0.0))
    assert unfixed_parameters(C, guess) == ("vy_mps", "vz_mps")
    assert unfixed_across_sight(C, guess, centre) == ()
    C[3:6, 3:6] += 100.0**2 * np.outer(across, across)
    assert unfixed_across_sight(C, guess, centre) == ("v_across_mps",)
    C[3, :] = C[:, 3] = np.nan
    assert unfixed_across_sight(C, guess, centre) == ("vx_mps", "v_across_mps")


def test_on_the_axis_a_vz_undetermined_by_rank_leaves_the_velocity_across_the_line_of_sight_fixed():
    """A NaN row of vz (the rank test's) does not reach v_across on the axis, where its weight is zero."""
    C = _cov(SMALL)
    C[5, :] = C[:, 5] = np.nan
    assert unfixed_across_sight(C, GUESS, (0.0, 0.0, 2.0)) == ()
    with pytest.raises(ValueError, match="sight_axes"):
        sight_axes((0.0, 0.0, 0.0))


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


# ------------------------------------------------------------- the limb model's error


def _serve_edges():
    from ballscan.geometry.camera import LineScanCamera
    from ballscan.solve.synthetic import synthetic_edges

    cam = LineScanCamera(2048, 4200.0, 1023.5, 70000.0, 1.2e-5, k1=-0.05)
    m = BallMotion(0.0335, 0.0017, (0, -0.08, 4.2), (44.5, 3.9, -5.5))
    return cam, m, synthetic_edges(cam, m, 240, edge_sigma_px=0.02, seed=0, add_noise=False)


def _displaced(e, side: str, offset_px: float, trend_px: float, curve_px: float = 0.0):
    """``e`` with one side's edges displaced by ``offset + trend * tau + curve * P2(tau)``, ``tau`` from -1 to 1 over that side's lines."""
    from dataclasses import replace

    x = getattr(e, f"{side}_px")
    ok = np.isfinite(x)
    t = e.t_s
    tau = 2.0 * (t - t[ok].min()) / (t[ok].max() - t[ok].min()) - 1.0
    return replace(e, **{f"{side}_px": np.where(ok, x + offset_px + trend_px * tau + curve_px * (1.5 * tau**2 - 0.5), np.nan)})


@pytest.mark.parametrize("offset_px, trend_px, right_from", [(0.0, 0.05, 0), (0.04, 0.0, 0), (0.03, 0.05, 0), (0.0, 0.05, 50)])
def test_limb_covariance_equals_the_fits_moved_by_displaced_limbs(offset_px, trend_px, right_from):
    """Analytic against brute force: the added covariance is the sum of the outer products of the fits' moves
    when each side's edges are displaced by one sigma of the offset, of the trend and of the curvature in turn (noise-free edges,
    so the residuals add nothing); ``right_from``: the right side's edges only from that line on (the sides'
    lines and times differ)."""
    from dataclasses import replace

    from ballscan.solve.fit import fit_motion
    from ballscan.solve.settings import FitSettings

    cam, m, e = _serve_edges()
    right = e.right_px.copy()
    right[:right_from] = np.nan
    e = replace(e, right_px=right)
    s = FitSettings(limb_offset_sigma_px=offset_px, limb_trend_sigma_px=trend_px, limb_residual_gain=1.0, cost_tol=1e-12, stall_tol=0.0)
    base = fit_motion(cam, e, m, s)
    assert base.converged
    brute = np.zeros((6, 6))
    for side in ("left", "right"):
        for a, b, c in ((offset_px, 0.0, 0.0), (0.0, trend_px, 0.0), (0.0, 0.0, trend_px)):
            if a == b == c == 0.0:
                continue
            d = fit_motion(cam, _displaced(e, side, a, b, c), m, s).motion.to_params() - base.motion.to_params()
            brute += np.outer(d, d)
    limb = base.limb_covariance
    # to within 5 %, or 1 % of the parameter's whole sigma where the move is second order (z0, t_c)
    sig, total = np.sqrt(np.diag(brute)), np.sqrt(np.diag(base.covariance))
    assert np.all(np.abs(np.sqrt(np.diag(limb)) - sig) <= 0.05 * sig + 0.01 * total)
    assert np.all(np.abs(limb - brute) <= 0.01 * np.outer(total, total))
    assert np.allclose(base.statistical_covariance + limb, base.covariance)


def test_limb_covariance_is_zero_when_left_out():
    from ballscan.solve.fit import fit_motion
    from ballscan.solve.settings import FitSettings

    cam, m, e = _serve_edges()
    r = fit_motion(cam, e, m, FitSettings(limb_offset_sigma_px=0.0, limb_trend_sigma_px=0.0, limb_residual_gain=0.0))
    assert np.all(r.limb_covariance == 0.0)
    assert np.array_equal(r.statistical_covariance, r.covariance)


def test_smooth_residual_of_white_noise_is_small_and_of_a_slow_wave_its_rms():
    from ballscan.solve.uncertainty import smooth_residual_px

    rng = np.random.default_rng(3)
    sig = np.full(4000, 0.05)
    white = rng.normal(size=4000)
    assert smooth_residual_px(white, sig) < 0.1 * 0.05
    wave = 0.02 * np.sqrt(2.0) * np.sin(np.arange(4000) / 200.0)  # 0.02 px RMS over 1,257-line periods
    assert smooth_residual_px(white + wave / 0.05, sig) == pytest.approx(0.02, rel=0.1)
    assert smooth_residual_px(white[:15], sig[:15]) == 0.0  # fewer than two blocks


def test_a_clean_limb_adds_nothing_and_a_wavy_one_widens_the_velocity():
    """White edge noise leaves the limb term at 0 (its block means within white noise's spread); a 0.1 px
    wave along the left limb (texture, a 38-line period) adds it, chiefly to vz and t_c, beyond the
    residuals' own correlation scale (7-10x here)."""
    from dataclasses import replace

    from ballscan.geometry.camera import LineScanCamera
    from ballscan.solve.fit import fit_motion
    from ballscan.solve.synthetic import synthetic_edges

    cam = LineScanCamera(2048, 4200.0, 1023.5, 70000.0, 1.2e-5, k1=-0.05)
    m = BallMotion(0.0335, 0.0017, (0, -0.08, 4.2), (44.5, 3.9, -5.5))
    e = synthetic_edges(cam, m, 240, edge_sigma_px=0.05, seed=4)
    clean = fit_motion(cam, e, m)
    assert np.all(clean.limb_covariance == 0.0)
    # white noise above its stated sigma (reduced chi-square near 3) is still white
    rng = np.random.default_rng(7)
    noisy = replace(e, left_px=e.left_px + rng.normal(0.0, 0.1, e.t_s.size), right_px=e.right_px + rng.normal(0.0, 0.1, e.t_s.size))
    loud = fit_motion(cam, noisy, m)
    assert loud.chi2_red > 2.0
    assert np.all(loud.limb_covariance == 0.0)
    wave = 0.1 * np.sin(np.arange(e.t_s.size) / 6.0)
    wavy = fit_motion(cam, replace(e, left_px=e.left_px + wave), m)
    assert wavy.inflation > 5.0
    grow = np.sqrt(np.diag(wavy.covariance) / np.diag(wavy.statistical_covariance))
    assert grow[5] > 1.02 and grow[0] > 1.02


def test_significant_square_takes_a_component_in_the_measure_it_stands_out_of_its_noise():
    from ballscan.solve.uncertainty import SPEED_COMPONENT_VARIANCES, significant_square

    lo, hi = SPEED_COMPONENT_VARIANCES
    lam = 4.0
    # below the first threshold nothing, from the second the unbiased square a^2 - lambda
    assert significant_square(np.array([math.sqrt(lo * lam) * 0.999]), lam)[0] == 0.0
    assert significant_square(np.array([3.0 * math.sqrt(lam)]), lam)[0] == pytest.approx(8.0 * lam)
    # continuous in the measured component (no jump of the speed at either threshold)
    a = np.linspace(0.0, 2.0 * math.sqrt(hi * lam), 20001)
    f = significant_square(a, lam)
    assert np.all(np.diff(f) >= 0.0) and np.max(np.diff(f)) < 1e-2
    # a component of zero (or, rounded, negative) variance counts whole; a plain float works; NaN stays NaN
    assert significant_square(np.array([0.5]), 0.0)[0] == 0.25 and significant_square(0.5, -1e-18) == pytest.approx(0.25)
    assert np.isnan(significant_square(np.array([np.nan]), lam)[0]) and np.isnan(significant_square(np.array([1.0]), np.nan)[0])
