"""Levenberg-Marquardt on a least-squares problem, and :func:`scipy.optimize.least_squares` as a cross-check.

A problem is any object with ``residuals(x)`` (the whitened residuals,
ndarray (M,)) and ``residuals_and_jacobian(x)`` (those and their Jacobian,
(M, p)); :class:`ballscan.solve.problem.FitProblem` is the refinement's
(Zhao & Wen, Eq. (7)-(10)).  Non-convergence is a status of the returned
:class:`SolveResult`, never an exception.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Protocol

import numpy as np

from ._fit_kernels import damped, equilibrated
from .settings import FitSettings

__all__ = ["LeastSquaresProblem", "SolveResult", "levenberg_marquardt", "scipy_least_squares"]


class LeastSquaresProblem(Protocol):
    """What the solvers need of a problem."""

    def residuals(self, x: np.ndarray) -> np.ndarray: ...

    def residuals_and_jacobian(self, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]: ...


@dataclass(frozen=True)
class SolveResult:
    """Outcome of a solve.

    Attributes
    ----------
    x : ndarray (p,)
        The solution (the parameters' units).
    n_evaluations : int
        Residual evaluations (a Jacobian counts as one).
    status : int
        > 0 converged, 0 stopped (evaluations spent or no step lowers the
        cost), scipy's status for :func:`scipy_least_squares`.
    message : str
        Why the solve ended.
    cost : float
        Half the (robust) chi-square at ``x``.
    residuals : ndarray (M,)
        Whitened residuals at ``x``.
    jacobian : ndarray (M, p)
        The last Jacobian, taken at or next to ``x``.
    """

    x: np.ndarray
    n_evaluations: int
    status: int
    message: str
    cost: float
    residuals: np.ndarray
    jacobian: np.ndarray

    @property
    def converged(self) -> bool:
        return self.status > 0


def _rho(z: np.ndarray, loss: str) -> tuple[np.ndarray, np.ndarray]:
    """Robust loss ``rho(z)`` and ``rho'(z)`` of squared whitened residuals (scipy's conventions)."""
    if loss == "linear":
        return z, np.ones_like(z)
    if loss == "soft_l1":
        q = np.sqrt(1.0 + z)
        return 2.0 * (q - 1.0), 1.0 / q
    if loss == "huber":
        big = z > 1.0
        sq = np.sqrt(np.where(big, z, 1.0))
        return np.where(big, 2.0 * sq - 1.0, z), np.where(big, 1.0 / sq, 1.0)
    raise ValueError(f"loss: expected 'linear', 'soft_l1' or 'huber', got {loss!r}")


def _cost(r: np.ndarray, loss: str, f2: float) -> float:
    """Half the robust chi-square of the whitened residuals ``r`` (loss scale ``f2`` squared sigmas)."""
    if loss == "linear":
        return 0.5 * float(r @ r)
    return 0.5 * f2 * float(_rho((r * r) / f2, loss)[0].sum())


def levenberg_marquardt(
    problem: LeastSquaresProblem, x0: np.ndarray, settings: FitSettings, start=None, loss: str | None = None
) -> SolveResult:
    """Levenberg-Marquardt with iteratively reweighted robust loss.

    Steps are solved on the column-equilibrated normal equations (the
    parameters' sizes differ by ~1e8).  It stops when the Gauss-Newton step
    would lower the cost by less than ``settings.cost_tol`` (in units of
    half the chi-square: 1e-5 is a move of about 0.003 sigma), which, unlike a
    relative ``ftol``, does not stop early along the weak ``vz`` direction.
    The Jacobian is computed at the start (or taken from ``start = (r, J)``;
    ``r`` None is recomputed) and after accepted steps that lowered the cost
    by more than ``settings.jacobian_refresh`` (other steps are chord steps
    with the previous one); with ``settings.broyden`` it is instead
    corrected after every trial step by Broyden's rank-one update, so that
    a step costs one model evaluation.

    Parameters
    ----------
    problem : LeastSquaresProblem
    x0 : ndarray (p,)
        Start.
    settings : FitSettings
        ``cost_tol``, ``stall_tol``, ``jacobian_refresh``, ``broyden``,
        ``max_nfev``, ``f_scale`` and (default) ``loss``.
    start : tuple, optional
        ``(r, J)`` at ``x0``.
    loss : str, optional
        The robust loss (default ``settings.loss``).
    """
    f2 = settings.f_scale**2
    tol = settings.cost_tol
    loss = settings.loss if loss is None else loss
    linear = loss == "linear"
    x = np.asarray(x0, dtype=float).copy()
    if start is None:
        r, J = problem.residuals_and_jacobian(x)
        n_eval = 1
    else:
        r, J = start
        J = J.copy()
        n_eval = 0
        if r is None:
            r = problem.residuals(x)
            n_eval = 1
    cost = _cost(r, loss, f2)
    lam = 1e-3
    broyden = settings.broyden
    n_fresh = 0
    normal_of = None  # the weighted Jacobian whose normal matrix A and column norms cn are at hand
    while n_eval < settings.max_nfev:
        if linear:
            Jw, rw = J, r
        else:
            w = np.sqrt(_rho((r * r) / f2, loss)[1])
            Jw, rw = J * w[:, None], r * w
        if Jw is not normal_of:
            # the column-equilibrated normal matrix from J^T J (a chord step
            # with the same Jacobian reuses it)
            cn, A = equilibrated(Jw.T @ Jw)
            normal_of = Jw
        g = (Jw.T @ rw) / cn
        try:
            step = -np.linalg.solve(damped(A, lam), g)
        except np.linalg.LinAlgError:
            step = -np.linalg.lstsq(A + lam * np.eye(A.shape[0]), g, rcond=None)[0]
        predicted = -(g @ step)  # first-order decrease of 0.5 * chi2
        if predicted < tol:
            if broyden and n_fresh == 0 and n_eval > 1:
                # confirm with an exact Jacobian before declaring convergence
                r, J = problem.residuals_and_jacobian(x)
                n_eval += 1
                n_fresh = 1
                continue
            return SolveResult(x, n_eval, 1, f"converged: predicted cost decrease below {tol:g}", cost, r, J)
        dx = step / cn
        x_new = x + dx
        r_new = problem.residuals(x_new)
        n_eval += 1
        ok = bool(np.all(np.isfinite(r_new)))
        if broyden and ok:
            J = J + np.outer(r_new - r - J @ dx, dx) / float(dx @ dx)
        cost_new = _cost(r_new, loss, f2) if ok else math.inf
        if cost_new <= cost:
            lam = max(lam / 10.0, 1e-9)
            x, cost, r = x_new, cost_new, r_new
            n_fresh = 0
            if not broyden and predicted > settings.jacobian_refresh:
                # far from the minimum: the model's curvature matters, take
                # a fresh Jacobian; close to it the old one is kept (a chord
                # step costs one evaluation and moves well below a sigma)
                r, J = problem.residuals_and_jacobian(x)
                n_eval += 1
        else:
            if predicted < settings.stall_tol and cost_new - cost <= settings.stall_tol and _gn_decrease(A, g) < settings.stall_tol:
                # the last hundredths of a sigma (the undamped step's too, so
                # that heavy damping cannot fake it): the averaged model's
                # quadrature is not smooth at this scale, and damping the
                # step further only spends evaluations
                message = f"converged: no step lowers the cost, predicted decrease below {settings.stall_tol:g}"
                return SolveResult(x, n_eval, 1, message, cost, r, J)
            lam *= 10.0
            if lam > 1e10:
                return SolveResult(x, n_eval, 0, "stopped: no step lowers the cost", cost, r, J)
    return SolveResult(x, n_eval, 0, f"stopped: {settings.max_nfev} evaluations", cost, r, J)


def _gn_decrease(A: np.ndarray, g: np.ndarray) -> float:
    """First-order decrease of half the chi-square along the undamped Gauss-Newton step (normal matrix ``A``, gradient ``g``)."""
    try:
        step = np.linalg.solve(A, g)
    except np.linalg.LinAlgError:
        step = np.linalg.lstsq(A, g, rcond=None)[0]
    return float(g @ step)


class _Both:
    """``problem.residuals_and_jacobian`` with the last point's value kept (scipy asks for both separately)."""

    __slots__ = ("problem", "key", "value")

    def __init__(self, problem: LeastSquaresProblem):
        self.problem, self.key, self.value = problem, None, None

    def __call__(self, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        key = x.tobytes()
        if key != self.key:
            self.key, self.value = key, self.problem.residuals_and_jacobian(x)
        return self.value

    def residuals(self, x: np.ndarray) -> np.ndarray:
        return self(x)[0]

    def jacobian(self, x: np.ndarray) -> np.ndarray:
        return self(x)[1]


def scipy_least_squares(
    problem: LeastSquaresProblem, x0: np.ndarray, settings: FitSettings, x_scale: np.ndarray, loss: str
) -> SolveResult:
    """:func:`scipy.optimize.least_squares` (``trf``, tolerances 1e-12) on ``problem``, scaled by ``x_scale`` (the parameters' units)."""
    both = _Both(problem)
    from scipy.optimize import least_squares  # the cross-check only: scipy.optimize loads then

    res = least_squares(
        both.residuals, x0, jac=both.jacobian, x_scale=x_scale, loss=loss, f_scale=settings.f_scale, method="trf",
        max_nfev=settings.max_nfev, xtol=1e-12, ftol=1e-12, gtol=1e-12,
    )
    r_end, J_end = problem.residuals_and_jacobian(res.x)
    return SolveResult(res.x, int(res.nfev), int(res.status), str(res.message), float(res.cost), r_end, J_end)
