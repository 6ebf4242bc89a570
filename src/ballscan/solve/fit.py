"""Weighted nonlinear least-squares fit of the ball's motion to measured edges (the refinement, Zhao & Wen Eq. (7)-(10)).

The model is the averaged silhouette of :mod:`ballscan.model.averaged` (the
paper's dynamic sphere, first Eq. (8), seen through the camera of Eq. (1),
averaged over the pixel's height and the exposure), fitted over ``theta =
(t_c, y0, z0, vx, vy, vz)`` (:data:`ballscan.geometry.motion.PARAM_NAMES`)
and optionally a symmetric edge bias, from the initial guess of Eq. (3)-(7)
(:mod:`ballscan.solve.initial`).  :func:`fit_motion` fits one camera's
edges; :func:`fit_blocks` any number of residual blocks (cameras) sharing
the motion.

The steps: build each block's selection and weights
(:class:`ballscan.solve.problem.BlockState`), solve the stacked problem
(:class:`ballscan.solve.problem.FitProblem`) by Levenberg-Marquardt
(:func:`ballscan.solve.solver.levenberg_marquardt`), reject edges whose
residual exceeds ``reject_sigma`` robust sigmas (a seam crossing the limb),
re-select at the solution and solve again, at most ``max_reject_rounds``
times; then the covariance of :mod:`ballscan.solve.uncertainty`.  The lines
the ball enters or leaves during the exposure are levelled only when they
agree with the rest of the fit (:func:`_partial_verdict`).
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, field, replace

import numpy as np

from ..compiled import as_arg
from ._fit_kernels import loose_rows, on_both_sides
from ..geometry.camera import LineScanCamera
from ..geometry.motion import PARAM_NAMES, BallMotion
from ..measure.robust import median as _median
from ..measure.edges import EdgeMeasurements
from ..model.averaged import ModelEdges
from .problem import BlockState, FitProblem, ResidualBlock, Selection
from .settings import FitSettings
from .prior import Prior, WithPrior
from .solver import SolveResult, levenberg_marquardt, scipy_least_squares
from .uncertainty import covariance_from_jacobian, edge_sides, limb_covariance, residual_scale

__all__ = ["FitResult", "fit_blocks", "fit_motion"]


@dataclass(frozen=True)
class FitResult:
    """Outcome of :func:`fit_motion`.

    Attributes
    ----------
    motion : BallMotion
        The fitted motion (camera frame; ``V.x >= 0`` unless the camera
        states the crossing direction).
    covariance : ndarray (6, 6)
        Covariance of ``(t_c, y0, z0, vx, vy, vz)`` (s, m, m/s): the
        statistical part, scaled by ``max(1, chi2_red)`` and the residuals'
        correlation (:mod:`ballscan.solve.uncertainty`), plus
        ``limb_covariance``; NaN rows/columns for undetermined parameters.
    limb_covariance : ndarray (6, 6) or None
        The part of ``covariance`` due to the limb model's error
        (:func:`ballscan.solve.uncertainty.limb_covariance`), which more
        lines do not shrink; None where no fit was made.
    chi2_red : float
        Robust cost ``2 * cost / (m - p)`` (equal to the reduced chi-square
        when no residual exceeds the loss scale).
    residual_rms_px : float
        RMS of the edge residuals, pixels.
    n_iterations : int
        Function evaluations of the optimiser.
    status : int
    message : str
    converged : bool
    undetermined : tuple of str
        Parameter names (``PARAM_NAMES``) that the data cannot determine.
    edge_bias_px : float
        Fitted symmetric edge bias (0 when not fitted).
    edge_bias_sigma_px : float
    n_edges, n_area_lines : int
        Residuals used.
    run_time_s : float
        Wall time of the fit.
    flags : tuple of str
        geometry.md flag words (``not_converged``, ``degenerate``).
    n_rejected : int
        Edges rejected as outliers (``FitSettings.reject_sigma``).
    inflation : float
        Factor applied to the covariance for correlated residuals
        (``FitSettings.correlation_inflation``).
    partial_levelled : bool
        The lines the ball enters or leaves during the exposure were fitted
        with their levelled areas (``FitSettings.area_level_partial`` or
        ``area_partial_check``) in the returned fit.
    partial_verdict : str
        What ``area_partial_check`` decided: ``"off"`` (not run: 0, the
        pixel fit or ``area_level_partial``), ``"one_end"`` (such lines at
        one end of the ball only: loose), ``"none"`` (no such line with a
        level), ``"agree"`` (levelled) or ``"disagree"`` (the loose fit, from
        the start; ``n_iterations`` and ``run_time_s`` then count both fits;
        also ``"one_end"`` when the levelled fit's solution has such lines
        at one end only).
    """

    motion: BallMotion
    covariance: np.ndarray
    chi2_red: float
    residual_rms_px: float
    n_iterations: int
    status: int
    message: str
    converged: bool
    undetermined: tuple[str, ...] = ()
    edge_bias_px: float = 0.0
    edge_bias_sigma_px: float = 0.0
    n_edges: int = 0
    n_area_lines: int = 0
    run_time_s: float = 0.0
    flags: tuple[str, ...] = field(default=())
    n_rejected: int = 0
    inflation: float = 1.0
    partial_levelled: bool = False
    partial_verdict: str = "off"
    limb_covariance: np.ndarray | None = None

    @property
    def sigmas(self) -> np.ndarray:
        """1-sigma of the six parameters (s, m, m, m/s, m/s, m/s)."""
        return np.sqrt(np.diag(self.covariance))

    @property
    def statistical_covariance(self) -> np.ndarray:
        """``covariance`` without the limb model's part: what the image's measurements fix."""
        return self.covariance if self.limb_covariance is None else self.covariance - self.limb_covariance

    @property
    def degenerate(self) -> bool:
        return bool(self.undetermined)



def fit_motion(
    camera: LineScanCamera,
    edges: EdgeMeasurements,
    initial: BallMotion,
    settings: FitSettings = FitSettings(),
    prior: Prior | None = None,
) -> FitResult:
    """Fit the averaged-silhouette model to one ball's edge measurements (Eq. (7)-(10)).

    Parameters
    ----------
    camera : LineScanCamera
    edges : EdgeMeasurements
        From :func:`ballscan.measure.edges.measure_edges` (or
        :func:`ballscan.solve.synthetic.synthetic_edges`).
    initial : BallMotion
        Starting point (e.g. the paper's key-point guess, Eq. (3)-(7)); its
        radius and known acceleration are kept fixed.
    settings : FitSettings
    prior : ParameterPrior or VelocityPrior or None
        A Gaussian prior on one parameter or on the velocity along a
        direction, one more residual of the fit
        (:mod:`ballscan.solve.prior`); its covariance holds it too.

    Returns
    -------
    FitResult
        Never raises for a degenerate geometry: ``undetermined`` names the
        parameters the image cannot determine and ``converged`` is False when
        the optimiser did not converge.
    """
    return fit_blocks((ResidualBlock(camera, edges),), initial, settings, prior)


def fit_blocks(blocks, initial: BallMotion, settings: FitSettings = FitSettings(), prior: Prior | None = None) -> FitResult:
    """Fit the motion shared by residual blocks (one per camera) to their measurements (Eq. (7)-(10)).

    Parameters
    ----------
    blocks : sequence of ResidualBlock
        The measurements; the first block's camera states the crossing
        direction (the sign of ``V.x``) and the solver's parameter scale.
    initial : BallMotion
        Starting point; its radius and known acceleration are kept fixed.
    settings : FitSettings
    prior : ParameterPrior or VelocityPrior or None
        As :func:`fit_motion`'s.

    Returns
    -------
    FitResult
        As :func:`fit_motion`'s; counts (``n_edges``, ...) summed over the blocks.
    """
    t0 = time.perf_counter()
    states = tuple(BlockState(b, initial, settings) for b in blocks)
    theta0 = initial.to_params()
    # the partial lines levelled (area_partial_check: first, then tested)
    level_partial = settings.area_partial_check > 0 and not settings.area_level_partial and not settings.pixels
    verdict = "off"
    sels = _select_all(states, theta0, level_partial)
    if level_partial and not _partials_at_both_ends(states, sels, theta0):
        # not at both ends (a ball cut by the image's first or last line): loose
        level_partial, verdict = False, "one_end"
        sels = _select_all(states, theta0, level_partial)
    # the symmetric edge bias needs both edges of a line; the motion takes
    # one-sided lines too (a ball cut by the sensor's end), two for a pair
    n_edge_lines = sum(s.n_edge_lines for s in sels)
    fit_b = settings.fit_edge_bias and n_edge_lines >= settings.min_edge_lines
    n_pairs = sum(s.n_line_pairs for s in sels)
    if n_pairs < settings.min_edge_lines or sum(s.n_residuals for s in sels) <= 6 + int(fit_b):
        return _degenerate_result(initial, n_pairs, settings, sels, t0)
    x0 = np.concatenate([theta0, [0.0]]) if fit_b else theta0.copy()
    rounds = _solve_rounds(states, sels, x0, level_partial, settings, prior)
    sol = rounds.solution
    if level_partial and sol is not None:
        # an unfinished levelled solve (J^T r != 0) would mix its own step into the test's
        verdict = _partial_verdict(states, rounds.solved, sol, settings) if sol.converged else "disagree"
        if verdict in ("disagree", "one_end"):
            # the fit with those lines loose, from the start (its outlier
            # rounds and its path along the weak V.z direction would
            # otherwise depend on the levelled fit's)
            loose = fit_blocks(blocks, initial, replace(settings, area_partial_check=0.0), prior)
            n_iter = loose.n_iterations + rounds.n_evaluations
            return replace(loose, n_iterations=n_iter, run_time_s=time.perf_counter() - t0, partial_verdict=verdict)
    if sol is None:
        return _degenerate_result(initial, sum(s.n_line_pairs for s in rounds.last), settings, rounds.last, t0)
    return _result(states, initial, rounds, level_partial, verdict, settings, t0)


@dataclass(frozen=True)
class _Rounds:
    """Outcome of the solve-reject-reselect rounds.

    Attributes
    ----------
    solution : SolveResult or None
        The last solve (None: no round had enough edges).
    solved : tuple of Selection
        The selections it solved (one per block).
    last : tuple of Selection
        The last selections made (a later re-selection that left too few
        edges is not solved).
    n_evaluations : int
        Residual evaluations over all solves.
    n_rejected : int
        Edges rejected as outliers.
    """

    solution: SolveResult | None
    solved: tuple
    last: tuple
    n_evaluations: int
    n_rejected: int


def _select_all(states, theta: np.ndarray, level_partial: bool) -> tuple[Selection, ...]:
    return tuple(st.select(theta, level_partial) for st in states)


def _solve(states, sels, x: np.ndarray, loss: str, settings: FitSettings, prior: Prior | None) -> SolveResult:
    """One solve of the stacked problem at the selections ``sels`` from ``x`` (with the prior's residual last)."""
    problem = FitProblem(states, sels, fit_bias=len(x) == 7)
    if prior is not None:
        problem = WithPrior(problem, prior)
    if settings.solver == "scipy":
        scale = states[0].scale
        x_scale = np.concatenate([scale, [0.05]]) if len(x) == 7 else scale
        return scipy_least_squares(problem, x, settings, x_scale, loss)
    return levenberg_marquardt(problem, x, settings, start=problem.start(), loss=loss)


def _solve_rounds(states, sels, x: np.ndarray, level_partial: bool, settings: FitSettings, prior: Prior | None = None) -> _Rounds:
    """(Optionally a robust fit first, then) least squares, rejection of outlying edges, re-selection and refit until nothing changes."""
    n_total = n_rejected = 0
    sol, solved = None, ()
    if settings.robust_first:
        sol, solved = _solve(states, sels, x, settings.loss, settings, prior), sels
        x, n_total = sol.x, n_total + sol.n_evaluations
        sels = _select_all(states, x[:6], level_partial)
    for rnd in range(max(settings.max_reject_rounds, 0) + 1):
        if rnd > 0:
            sels = _select_all(states, x[:6], level_partial)
        if sum(s.n_line_pairs for s in sels) < settings.min_edge_lines:
            break
        sol, solved = _solve(states, sels, x, "linear", settings, prior), sels
        x, n_total = sol.x, n_total + sol.n_evaluations
        if rnd == settings.max_reject_rounds or settings.reject_sigma <= 0:
            break
        n_bad = _reject(states, sels, sol.residuals, settings.reject_sigma)
        if not n_bad:
            break
        n_rejected += n_bad
    return _Rounds(sol, solved, sels, n_total, n_rejected)


def _reject(states, sels, r: np.ndarray, reject_sigma: float) -> int:
    """Mark each block's edges whose whitened residual exceeds ``reject_sigma`` robust sigmas (``max(1, 1.4826 MAD)``); their number."""
    n_bad = 0
    o = 0
    for st, sel in zip(states, sels):
        nl, nr = sel.n_left, sel.n_right
        if nl + nr > 0:
            re = r[o : o + nl + nr]
            robust = max(1.0, 1.4826 * float(_median(np.abs(re - _median(re)))))
            bad = np.abs(re) > reject_sigma * robust
            if bad.any():
                st.rejected_left[np.flatnonzero(sel.use_left)[bad[:nl]]] = True
                st.rejected_right[np.flatnonzero(sel.use_right)[bad[nl:]]] = True
                n_bad += int(bad.sum())
        o += sel.n_residuals
    return n_bad


def _correlated_runs(sels, r: np.ndarray) -> list[tuple[np.ndarray, ...]]:
    """Each block's :meth:`Selection.correlated_runs` of ``r`` (views): its left and right edges first."""
    ends = np.cumsum([0] + [sel.n_residuals for sel in sels])
    return [sel.correlated_runs(r[a:b]) for sel, a, b in zip(sels, ends[:-1], ends[1:])]


def _result(states, initial: BallMotion, rounds: _Rounds, level_partial: bool, verdict: str, settings: FitSettings, t0: float) -> FitResult:
    """The :class:`FitResult` of the last solve: chi-square, covariance (:mod:`ballscan.solve.uncertainty`), the reported sign of ``V.x``."""
    sol, sels = rounds.solution, rounds.solved
    r, x = sol.residuals, sol.x
    fit_b = len(x) == 7
    th, b = x[:6], (x[6] if fit_b else 0.0)
    levelled = (level_partial or settings.area_level_partial) and any(
        bool(_partial_lines(sel.use_area, st.model_at(th), st).any()) for st, sel in zip(states, sels)
    )
    # the pixel windows' (or ends') free brightnesses are parameters too
    dof = r.size - len(x) - sum(s.n_groups for s in sels)
    chi2_red = float(np.sum(r * r) / dof) if dof > 0 else math.nan
    runs = _correlated_runs(sels, r)
    sides = [block[:2] for block in runs]
    total_scale, inflation = residual_scale(chi2_red, tuple(a for block in runs for a in block), settings.correlation_inflation)
    cov_full, undetermined = covariance_from_jacobian(sol.jacobian, total_scale)
    limb_sides = edge_sides(sels, [st.block.edges.t_s for st in states], r)
    limb_full = limb_covariance(
        sol.jacobian, cov_full / total_scale, limb_sides, settings.limb_offset_sigma_px, settings.limb_trend_sigma_px,
        settings.limb_residual_gain,
    )
    limb = limb_full[:6, :6].copy()
    cov = cov_full[:6, :6] + limb
    for name in undetermined:
        k = PARAM_NAMES.index(name)
        cov[k, :] = limb[k, :] = np.nan
        cov[:, k] = limb[:, k] = np.nan
    edge_res = np.concatenate([a * s for (rl, rr), sel in zip(sides, sels) for a, s in ((rl, sel.sigma_left), (rr, sel.sigma_right))])
    rms = float(np.sqrt(np.mean(edge_res**2))) if edge_res.size else math.nan
    # report V.x >= 0 unless the crossing is known (the image cannot tell; geometry.md)
    th = th.copy()
    camera = states[0].block.camera
    sign = camera.crossing_sign if camera.crossing is not None else 1.0
    if np.sign(th[3]) != sign and not np.any(initial.acceleration_mps2):
        th[3] = -th[3]
        for c in (cov, limb):
            c[3, :] *= -1
            c[:, 3] *= -1
    flags = (("not_converged",) if not sol.converged else ()) + (("degenerate",) if undetermined else ())
    return FitResult(
        motion=BallMotion.from_params(th, initial.radius_m, initial.acceleration_mps2),
        covariance=cov,
        limb_covariance=limb,
        chi2_red=chi2_red,
        residual_rms_px=rms,
        n_iterations=rounds.n_evaluations,
        status=sol.status,
        message=sol.message,
        converged=sol.converged,
        undetermined=undetermined,
        edge_bias_px=float(b),
        edge_bias_sigma_px=float(math.sqrt(cov_full[6, 6] + limb_full[6, 6])) if fit_b else 0.0,
        n_edges=sum(s.n_left + s.n_right for s in sels),
        n_area_lines=sum(s.n_area for s in sels),
        run_time_s=time.perf_counter() - t0,
        flags=flags,
        n_rejected=rounds.n_rejected,
        inflation=inflation,
        partial_levelled=levelled,
        partial_verdict=verdict,
    )


def _degenerate_result(initial: BallMotion, n_edge_lines: int, settings: FitSettings, sels, t0: float) -> FitResult:
    return FitResult(
        motion=initial,
        covariance=np.full((6, 6), np.nan),
        chi2_red=math.nan,
        residual_rms_px=math.nan,
        n_iterations=0,
        status=-10,
        message=f"too few usable edge lines ({n_edge_lines} < {settings.min_edge_lines})",
        converged=False,
        undetermined=PARAM_NAMES,
        n_edges=sum(s.n_left + s.n_right for s in sels),
        n_area_lines=sum(s.n_area for s in sels),
        run_time_s=time.perf_counter() - t0,
        flags=("degenerate",),
    )


# ------------------------------------------------------- the partial lines


def _pinv_sym(a: np.ndarray) -> np.ndarray:
    """Pseudo-inverse of a small symmetric positive semi-definite matrix (eigenvalues below 1e-10 of the largest dropped)."""
    w, v = np.linalg.eigh(a)
    inv = np.where(w > 1e-10 * max(float(w.max()), 1e-300), 1.0 / np.where(w > 0, w, 1.0), 0.0)
    return (v * inv) @ v.T


def _partial_lines(use_a: np.ndarray, me: ModelEdges, st: BlockState) -> np.ndarray:
    """Area lines seen during part of the exposure (model presence in (0, 0.999)) that have a level."""
    pres = me.presence[0]
    return use_a & (pres > 0) & (pres < 0.999) & st.tables.levelled


def _at_both_ends(lines: np.ndarray, t_s: np.ndarray, t_c_s: float) -> bool:
    """Whether the mask ``lines`` holds lines both before and after ``t_c_s`` (line times ``t_s``)."""
    return bool(on_both_sides(as_arg(lines, np.bool_), as_arg(t_s), float(t_c_s)))


def _partials_at_both_ends(states, sels, theta: np.ndarray) -> bool:
    """Whether every block's partial lines at ``theta`` lie at both ends of the ball."""
    return all(
        _at_both_ends(_partial_lines(sel.use_area, st.model_at(theta), st), st.block.edges.t_s, theta[0])
        for st, sel in zip(states, sels)
    )


def _partial_verdict(states, sels, sol: SolveResult, settings: FitSettings) -> str:
    """Whether the levelled areas of the partial lines may stay in the fit (``area_partial_check``).

    ``sels`` and ``sol`` are the solved selections with those lines
    levelled and the solve (whitened residuals and Jacobian at the
    solution).  The loose fit (those lines' plain areas,
    :attr:`FitSettings.area_rel_sigma`) is one Gauss-Newton step away: from
    there each levelled area must lie within ``area_partial_check`` sigma of
    the model (its own sigma and the loose fit's prediction's in
    quadrature), and the move between the two solutions must pass a Hausman
    test at the false-alarm rate ``partial_shift_p``: with the added lines
    consistent it has the covariance ``C_loose - C_levelled``.  Both ends of
    the ball need such lines: a ball cut by the first or last line has one
    end, which then fixes ``t_c``, V.x and V.z nearly alone.  Both tests use
    the fits' unscaled sigmas (no reduced chi-square or correlation
    inflation), so on real images they fail more often than
    ``partial_shift_p`` says; failing only costs the loose fit.

    Returns
    -------
    str
        ``"none"`` (no partial line is levelled), ``"one_end"``, ``"agree"``
        or ``"disagree"``.
    """
    x = sol.x
    parts = []  # per block: rows, levelled sigma, loose sigma, model, loose area, levelled area, levelled area's sigma
    o = 0
    for st, sel in zip(states, sels):
        me = st.model_at(x[:6])
        partial = _partial_lines(sel.use_area, me, st)
        if partial.any():
            if not _at_both_ends(partial, st.block.edges.t_s, float(x[0])):
                return "one_end"
            pa = np.flatnonzero(partial[sel.use_area])  # among the area rows
            lines = np.flatnonzero(sel.use_area)[pa]
            T = st.tables
            parts.append((o + sel.n_left + sel.n_right + pa, sel.sigma_area[pa], T.sigma_area[lines], me.area_px[0][lines],
                          T.area[lines], T.area_levelled[lines], T.sigma_area_levelled[lines]))
        o += sel.n_residuals
    if not parts:
        return "none"
    rows, sa, sa_loose, model, ma, ma_lev, sa_lev = (np.concatenate(c) for c in zip(*parts))
    # those rows loose (the model's area derivatives, pixels, over the loose
    # sigmas), both Jacobians equilibrated by the loose one's column norms
    r_l, Jl_n, Jt_n, gn = loose_rows(as_arg(sol.jacobian), as_arg(sol.residuals), rows, as_arg(sa), as_arg(sa_loose), as_arg(model), as_arg(ma))
    c_l, c_t = _pinv_sym(Jl_n.T @ Jl_n), _pinv_sym(Jt_n.T @ Jt_n)
    step = -c_l @ (Jl_n.T @ r_l)  # to the loose solution (equilibrated parameters)
    pred = model + gn @ step
    var_pred = np.einsum("ij,jk,ik->i", gn, c_l, gn)
    z = (pred - ma_lev) / np.sqrt(sa_lev**2 + var_pred)
    if not np.all(np.abs(z) <= settings.area_partial_check):
        return "disagree"
    diff = c_l - c_t
    w, v = np.linalg.eigh(0.5 * (diff + diff.T))
    keep = w > 1e-9 * max(float(w.max()), 1e-300)
    if not keep.any():
        return "agree"
    d = v[:, keep].T @ step
    stat = float(np.sum(d * d / w[keep]))
    from scipy.special import chdtri  # scipy.special loads with the first partial end tested

    return "agree" if stat <= float(chdtri(int(keep.sum()), settings.partial_shift_p)) else "disagree"
