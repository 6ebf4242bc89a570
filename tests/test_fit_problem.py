"""The fitting problem stacks residual blocks: residuals concatenate, Jacobian rows stack, two copies halve the covariance."""

from __future__ import annotations

import numpy as np
import pytest

from ballscan.geometry.camera import LineScanCamera
from ballscan.geometry.motion import BallMotion
from ballscan.solve.fit import fit_blocks, fit_motion
from ballscan.solve.problem import BlockState, FitProblem, ResidualBlock
from ballscan.solve.settings import FitSettings
from ballscan.solve.solver import SolveResult, levenberg_marquardt
from ballscan.solve.synthetic import synthetic_edges


def _scene():
    cam = LineScanCamera(2048, 4200.0, 1023.5, 70000.0, 1.2e-5, k1=-0.05)
    m = BallMotion(0.0335, 0.0017, (0, -0.08, 4.2), (44.5, 3.9, -5.5))
    init = BallMotion(0.0335, 0.00172, (0, -0.079, 4.3), (43.0, 3.5, -3.0))
    return cam, m, init


@pytest.mark.parametrize("reach", [0.8, 0.0])
def test_two_blocks_stack_residuals_and_jacobian_rows(reach):
    cam, m, init = _scene()
    e = synthetic_edges(cam, m, 240, edge_sigma_px=0.02, seed=0)
    st = FitSettings(jacobian_reach=reach)
    block = ResidualBlock(cam, e)
    one = BlockState(block, init, st)
    a, b = BlockState(block, init, st), BlockState(block, init, st)
    x = init.to_params()
    sel = one.select(x, False)
    p1 = FitProblem((one,), (sel,), fit_bias=False)
    p2 = FitProblem((a, b), (a.select(x, False), b.select(x, False)), fit_bias=False)
    r1, J1 = p1.residuals_and_jacobian(x)
    r2, J2 = p2.residuals_and_jacobian(x)
    assert p2.block_sizes == (r1.size, r1.size)
    assert np.array_equal(r2, np.concatenate([r1, r1]))
    assert np.array_equal(J2, np.vstack([J1, J1]))
    assert np.array_equal(p2.residuals(x), r2) and np.array_equal(p2.jacobian(x), J2)


def test_fit_over_two_identical_blocks_halves_the_covariance():
    cam, m, init = _scene()
    e = synthetic_edges(cam, m, 240, edge_sigma_px=0.02, seed=0, add_noise=False)
    st = FitSettings(correlation_inflation=False)
    block = ResidualBlock(cam, e)
    one = fit_blocks((block,), init, st)
    two = fit_blocks((block, block), init, st)
    assert one.converged and two.converged
    sig = one.sigmas
    assert np.all(np.abs(two.motion.to_params() - one.motion.to_params()) < 1e-3 * sig)
    assert np.allclose(two.covariance, one.covariance / 2.0, rtol=1e-3, atol=0.0)
    assert two.n_edges == 2 * one.n_edges and two.n_area_lines == 2 * one.n_area_lines
    # the one-block fit is fit_motion
    ref = fit_motion(cam, e, init, st)
    assert np.array_equal(ref.motion.to_params(), one.motion.to_params()) and np.array_equal(ref.covariance, one.covariance)


def test_solver_reports_non_convergence_as_a_status():
    cam, m, init = _scene()
    e = synthetic_edges(cam, m, 240, edge_sigma_px=0.02, seed=0)
    st = FitSettings(max_nfev=2)
    state = BlockState(ResidualBlock(cam, e), init, st)
    x = init.to_params()
    out = levenberg_marquardt(FitProblem((state,), (state.select(x, False),), False), x, st, loss="linear")
    assert isinstance(out, SolveResult) and not out.converged and out.status == 0 and "evaluations" in out.message
    assert out.residuals.shape[0] == out.jacobian.shape[0]


def _one_sided(e, side: str):
    """The edges with one side's edges unusable on every line (a ball cut by that sensor end)."""
    from dataclasses import replace

    n = e.lines.size
    return replace(e, **{f"{side}_ok": np.zeros(n, dtype=bool), f"{side}_px": np.full(n, np.nan), f"{side}_sigma_px": np.full(n, np.nan)})


@pytest.mark.parametrize("side", ["left", "right"])
def test_lines_with_one_edge_fit_the_motion(side):
    """A ball seen by one limb only (cut by a sensor end) is fitted from it: the truth within 3 sigma, full rank."""
    cam, m, init = _scene()
    e = _one_sided(synthetic_edges(cam, m, 240, edge_sigma_px=0.02, seed=1), side)
    fit = fit_motion(cam, e, init)
    assert fit.converged and not fit.undetermined
    z = (fit.motion.to_params() - m.to_params()) / fit.sigmas
    assert np.all(np.abs(z) < 3.0), z
    # one limb carries less information than two
    both = fit_motion(cam, synthetic_edges(cam, m, 240, edge_sigma_px=0.02, seed=1), init)
    assert np.all(fit.sigmas > both.sigmas)


def test_too_few_one_sided_lines_count_as_pairs():
    """min_edge_lines counts two one-edge lines as one pair."""
    cam, m, init = _scene()
    e = _one_sided(synthetic_edges(cam, m, 240, edge_sigma_px=0.02, seed=1), "left")
    n_right = int(e.right_ok.sum())
    assert not fit_motion(cam, e, init, FitSettings(min_edge_lines=n_right // 2)).degenerate
    bad = fit_motion(cam, e, init, FitSettings(min_edge_lines=n_right // 2 + 1))
    assert bad.degenerate and "too few" in bad.message


def test_beyond_sensor_marks_lines_reaching_past_either_end():
    from ballscan.model.averaged import ModelEdges
    from ballscan.solve.problem import beyond_sensor

    left = np.array([0.5, 5.0, 5.0, 3.0, 3.0])
    right = np.array([20.0, 20.0, 99.5, 3.0, 30.0])
    presence = np.array([1.0, 1.0, 1.0, 0.0, 0.5])
    spread = np.array([0.0, 0.0, 0.0, np.nan, 6.0])
    me = ModelEdges(left, right, presence, right - left, spread, np.ones(5, dtype=bool))
    # width 100: pixel 0 and 99 are the ends; the absent line (presence 0) is never past them
    assert beyond_sensor(me, 100).tolist() == [True, False, True, False, True]
