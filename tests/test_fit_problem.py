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
