"""One motion fitted to several cameras' edges at once: the joint fit of a rig (Zhao & Wen Eq. (7)-(10), one block per camera).

The parameters are the ball's world state ``(P, V)`` at a fixed rig time
``t_ref`` (Eq. (8) in the world frame, with the rig's gravity), each
unknown clock offset (s), and each camera's edge bias (pixels, where its
settings fit one).  Camera ``k``'s residuals are those of its own
:class:`ballscan.solve.problem.FitProblem` (its edges, areas and weights,
:class:`ballscan.solve.problem.BlockState`) at its own six parameters
``theta_k = camera_params(P, V)`` (:func:`ballscan.geometry.rig.camera_params`);
its Jacobian rows are the block's chained with ``d theta_k / d (P, V)``.
A :class:`ballscan.solve.constraint.Constraint` adds its rows as a prior.

Each camera's consistency with the others is tested after the fit: its own
block is solved alone on the same selection, and the rise of its
chi-square under the joint motion, ``delta_chi2`` (in units of its
covariance scale, which counts the correlation of its edge and of its pixel
residuals), is compared with the chi-square quantile of 6 degrees of
freedom at ``CONSISTENCY_P`` (a wrong pose gives thousands).
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, field

import numpy as np

from ..geometry.camera import LineScanCamera
from ..geometry.motion import PARAM_NAMES, BallMotion
from ..geometry.rig import WorldMotion, camera_params, world_crossing
from ..measure.edges import EdgeMeasurements
from .constraint import Constraint
from .fit import _reject
from .problem import BlockState, FitProblem, ResidualBlock
from .settings import FitSettings
from .solver import levenberg_marquardt
from .uncertainty import covariance_from_jacobian, edge_sides, limb_covariance, residual_scale

__all__ = ["CONSISTENCY_P", "JointCamera", "JointCameraFit", "JointLayout", "JointProblem", "JointResult", "STATE_NAMES", "fit_joint"]

#: False-alarm rate of the per-camera consistency test.
CONSISTENCY_P = 1e-4
#: The world state's parameters.
STATE_NAMES = ("x_m", "y_m", "z_m", "vx_mps", "vy_mps", "vz_mps")


@dataclass(frozen=True)
class JointCamera:
    """One camera's input to the joint fit.

    Attributes
    ----------
    name : str
    camera : LineScanCamera
        Posed in the rig's world frame.
    edges : EdgeMeasurements
        The ball's edges in this camera (its own fit's).
    clock_offset_s : float or None
        ``t_cam - t_rig`` (s); None: estimated.
    settings : FitSettings
        Its residuals' selection and weights.
    level_partial : bool
        The lines the ball enters or leaves during the exposure enter with
        their levelled areas (where its own fit found them consistent,
        :attr:`ballscan.solve.fit.FitResult.partial_levelled`).
    """

    name: str
    camera: LineScanCamera
    edges: EdgeMeasurements
    clock_offset_s: float | None
    settings: FitSettings = FitSettings()
    level_partial: bool = False


@dataclass(frozen=True)
class JointCameraFit:
    """How one camera agrees with the joint motion.

    Attributes
    ----------
    name : str
    n_residuals : int
    chi2_red : float
        Its whitened residuals' sum of squares over ``n_residuals - 6``, joint motion.
    chi2_red_own : float
        The same for its own motion (its block solved alone on the same selection).
    delta_chi2 : float
        ``(chi2_joint - chi2_own) / scale``: ~ chi-square with at most 6
        degrees of freedom for a consistent camera.
    consistent : bool
        ``delta_chi2`` below the quantile at :data:`CONSISTENCY_P`.
    scale : float
        Its covariance scale (reduced chi-square and correlated residuals,
        :func:`ballscan.solve.uncertainty.residual_scale`).
    t_c_s : float
        Its crossing time in its own clock under the joint motion (s).
    clock_offset_s, clock_offset_sigma_s : float
        Its clock offset (given or fitted) and the fitted one's 1-sigma (0 when given).
    edge_bias_px : float
    """

    name: str
    n_residuals: int
    chi2_red: float
    chi2_red_own: float
    delta_chi2: float
    consistent: bool
    scale: float
    t_c_s: float
    clock_offset_s: float
    clock_offset_sigma_s: float
    edge_bias_px: float = 0.0

    def to_dict(self) -> dict:
        return {
            "n_residuals": self.n_residuals,
            "chi2_red": self.chi2_red,
            "chi2_red_own": self.chi2_red_own,
            "delta_chi2": self.delta_chi2,
            "consistent": self.consistent,
            "t_c_s": self.t_c_s,
            "clock_offset_s": self.clock_offset_s,
            "clock_offset_sigma_s": self.clock_offset_sigma_s,
            "edge_bias_px": self.edge_bias_px,
        }


@dataclass(frozen=True)
class JointResult:
    """Outcome of :func:`fit_joint`.

    Attributes
    ----------
    motion : WorldMotion
        The ball at its crossing of the reference camera's plane (rig clock).
    covariance : ndarray (7, 7)
        Of ``(t_c, x, y, z, vx, vy, vz)`` (:data:`ballscan.solve.derived.WORLD_COVARIANCE_PARAMETERS`), world frame;
        NaN in the rows of the undetermined components, and in ``t_c``'s where
        the crossing moves with one of them (one along the reference plane's normal).
    parameter_names : tuple of str
        The fitted parameters: :data:`STATE_NAMES`, ``clock_offset_s:NAME``, ``edge_bias_px:NAME``.
    parameter_covariance : ndarray
        Their covariance.
    cameras : tuple of JointCameraFit
    chi2_red : float
    converged : bool
    message : str
    undetermined : tuple of str
        Names of :data:`STATE_NAMES` the data cannot determine.
    constraint : Constraint or None
    constraint_residuals : ndarray or None
        The constraint's whitened residuals at the solution.
    n_iterations : int
    run_time_s : float
    """

    motion: WorldMotion
    covariance: np.ndarray
    parameter_names: tuple[str, ...]
    parameter_covariance: np.ndarray
    cameras: tuple[JointCameraFit, ...]
    chi2_red: float
    converged: bool
    message: str
    undetermined: tuple[str, ...] = ()
    constraint: Constraint | None = None
    constraint_residuals: np.ndarray | None = field(default=None, repr=False)
    n_iterations: int = 0
    run_time_s: float = 0.0

    @property
    def sigmas(self) -> np.ndarray:
        """1-sigma of ``(t_c, x, y, z, vx, vy, vz)``."""
        return np.sqrt(np.abs(np.diag(self.covariance)))

    @property
    def consistent(self) -> bool:
        return all(c.consistent for c in self.cameras)


class JointLayout:
    """Where each parameter sits in ``x = (P, V, offsets of the unknown clocks, edge biases)`` and each camera's view of ``x``."""

    def __init__(self, cameras, t_ref_s: float, gravity_mps2, fit_bias):
        self.cameras = tuple(cameras)
        self.t_ref_s = float(t_ref_s)
        self.gravity = np.asarray(gravity_mps2, dtype=float)
        self.fit_bias = tuple(bool(b) for b in fit_bias)
        self.offset_index: list[int | None] = []
        self.bias_index: list[int | None] = []
        k = 6
        for c in self.cameras:
            self.offset_index.append(None if c.clock_offset_s is not None else k)
            k += c.clock_offset_s is None
        for b in self.fit_bias:
            self.bias_index.append(k if b else None)
            k += b
        self.n_params = k

    def offset(self, x: np.ndarray, k: int) -> float:
        """Camera ``k``'s clock offset (s): given, or fitted."""
        i = self.offset_index[k]
        return float(x[i]) if i is not None else float(self.cameras[k].clock_offset_s)

    def camera_x(self, x: np.ndarray, k: int) -> tuple[np.ndarray, np.ndarray]:
        """Camera ``k``'s block parameters (theta, and its bias) and ``d theta / d (P, V)``."""
        theta, J, _ = camera_params(x[:6], self.cameras[k].camera, self.t_ref_s, self.gravity, self.offset(x, k))
        i = self.bias_index[k]
        return (np.concatenate([theta, [x[i]]]) if i is not None else theta), J


class JointProblem:
    """The stacked, whitened residuals of every camera's block at its view of one world motion, and their Jacobian.

    Rows: each camera's block (:class:`ballscan.solve.problem.FitProblem`)
    in order, then the constraint's; columns: the :class:`JointLayout`'s.
    """

    def __init__(self, layout: JointLayout, states, selections, radius_m: float, constraint: Constraint | None):
        self.layout = layout
        self.radius_m = float(radius_m)
        self.constraint = constraint
        self.problems = tuple(FitProblem((st,), (sel,), fit_bias=b) for st, sel, b in zip(states, selections, layout.fit_bias))

    def residuals(self, x: np.ndarray) -> np.ndarray:
        lay = self.layout
        parts = [p.residuals(lay.camera_x(x, k)[0]) for k, p in enumerate(self.problems)]
        if self.constraint is not None:
            parts.append(self.constraint.residuals(x[:6], self.radius_m, lay.gravity))
        return np.concatenate(parts)

    def residuals_and_jacobian(self, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        lay = self.layout
        rs, rows = [], []
        for k, p in enumerate(self.problems):
            xk, Jt = lay.camera_x(x, k)
            r, Jb = p.residuals_and_jacobian(xk)
            J = np.zeros((r.size, lay.n_params))
            J[:, :6] = Jb[:, :6] @ Jt
            if lay.offset_index[k] is not None:
                J[:, lay.offset_index[k]] = Jb[:, 0]
            if lay.bias_index[k] is not None:
                J[:, lay.bias_index[k]] = Jb[:, 6]
            rs.append(r)
            rows.append(J)
        if self.constraint is not None:
            rs.append(self.constraint.residuals(x[:6], self.radius_m, lay.gravity))
            Jc = np.zeros((self.constraint.n_residuals, lay.n_params))
            Jc[:, :6] = self.constraint.jacobian(x[:6], self.radius_m, lay.gravity)
            rows.append(Jc)
        return np.concatenate(rs), np.vstack(rows)


def _chi2_quantile(dof: int, p: float) -> float:
    from scipy.special import chdtri

    return float(chdtri(dof, p))


def fit_joint(
    cameras,
    start: WorldMotion,
    clock_offsets_s=None,
    *,
    constraint: Constraint | None = None,
    settings: FitSettings | None = None,
) -> JointResult:
    """Fit one world motion to every camera's edges (and a constraint), Eq. (7)-(10) with the world motion of Eq. (8).

    Parameters
    ----------
    cameras : sequence of JointCamera
        The first camera with a known clock is the reference (the result's crossing).
    start : WorldMotion
        Starting state; its ``t_ref_s`` stays the fit's reference time and
        its gravity and radius are kept.
    clock_offsets_s : sequence of float, optional
        Starting values of the unknown clocks' offsets (s), in camera order
        (0 when not given).
    constraint : Constraint, optional
        A known plane or point, as a prior.
    settings : FitSettings, optional
        The solver's (tolerances, outlier rounds); the first camera's by default.

    Returns
    -------
    JointResult
    """
    t0 = time.perf_counter()
    cams = tuple(cameras)
    if not cams:
        raise ValueError("fit_joint: no camera")
    s = cams[0].settings if settings is None else settings
    g = np.asarray(start.gravity_mps2, dtype=float)
    unknown = [k for k, c in enumerate(cams) if c.clock_offset_s is None]
    offs0 = [0.0] * len(unknown) if clock_offsets_s is None else [float(v) for v in clock_offsets_s]
    x = np.concatenate([start.state, offs0])
    states = []
    for k, c in enumerate(cams):
        off = c.clock_offset_s if c.clock_offset_s is not None else offs0[unknown.index(k)]
        theta, _, _ = camera_params(start.state, c.camera, start.t_ref_s, g, off)
        acc = tuple(c.camera.rotation_matrix @ g)
        states.append(BlockState(ResidualBlock(c.camera, c.edges), BallMotion.from_params(theta, start.radius_m, acc), c.settings))
    fit_bias = tuple(c.settings.fit_edge_bias for c in cams)
    x = np.concatenate([x, np.zeros(sum(fit_bias))])
    n_eval = 0
    sol = problem = None
    layout = JointLayout(cams, start.t_ref_s, g, fit_bias)
    for rnd in range(max(s.max_reject_rounds, 0) + 1):
        sels = [st.select(layout.camera_x(x, k)[0][:6], c.level_partial) for k, (st, c) in enumerate(zip(states, cams))]
        problem = JointProblem(layout, states, sels, start.radius_m, constraint)
        sol = levenberg_marquardt(problem, x, s, loss="linear")
        x, n_eval = sol.x, n_eval + sol.n_evaluations
        if rnd == s.max_reject_rounds or s.reject_sigma <= 0:
            break
        n_cam = sum(sel.n_residuals for sel in sels)
        if not _reject(states, sels, sol.residuals[:n_cam], s.reject_sigma):
            break
    return _joint_result(problem, sol, states, start, constraint, n_eval, t0)


def _camera_fits(problem: JointProblem, sol, states) -> tuple[list[JointCameraFit], list[float]]:
    """Each camera's chi-square under the joint motion and alone, its consistency and covariance scale."""
    x, r, lay = sol.x, sol.residuals, problem.layout
    fits, scales = [], []
    o = 0
    q = _chi2_quantile(6, CONSISTENCY_P)
    for k, (p, st) in enumerate(zip(problem.problems, states)):
        sel = p.selections[0]
        n = sel.n_residuals
        rk = r[o : o + n]
        o += n
        xk, _ = lay.camera_x(x, k)
        dof = max(n - len(xk) - sel.n_groups, 1)
        chi2 = float(rk @ rk)
        own = levenberg_marquardt(FitProblem((st,), (sel,), fit_bias=lay.fit_bias[k]), xk, st.settings, loss="linear")
        chi2_own = float(own.residuals @ own.residuals)
        scale, _ = residual_scale(chi2_own / dof, sel.correlated_runs(rk), st.settings.correlation_inflation)
        delta = max(chi2 - chi2_own, 0.0) / scale
        i = lay.bias_index[k]
        fits.append(
            JointCameraFit(
                lay.cameras[k].name, n, chi2 / dof, chi2_own / dof, delta, bool(delta <= q), scale, float(xk[0]),
                lay.offset(x, k), 0.0, float(x[i]) if i is not None else 0.0,
            )
        )
        scales.append(scale)
    return fits, scales


def _limb(problem: JointProblem, sol, states) -> np.ndarray:
    """Each camera's limb error that the joint motion absorbs (:func:`ballscan.solve.uncertainty.limb_covariance`).

    The joint solve weighs each camera's residuals by their own sigmas
    alone, so its response to a displaced limb is that of the unscaled
    Jacobian ``sol.jacobian``.  The limb settings are the first camera's (a
    rig's cameras share them).
    """
    sels = [p.selections[0] for p in problem.problems]
    sides = edge_sides(sels, [st.block.edges.t_s for st in states], sol.residuals)
    cov_unit, _ = covariance_from_jacobian(sol.jacobian, 1.0)
    s = states[0].settings
    return limb_covariance(sol.jacobian, cov_unit, sides, s.limb_offset_sigma_px, s.limb_trend_sigma_px, s.limb_residual_gain)


def _joint_result(problem: JointProblem, sol, states, start: WorldMotion, constraint, n_eval: int, t0: float) -> JointResult:
    """Covariance (each camera's rows whitened by its own scale), the reference crossing and the per-camera reports."""
    fits, scales = _camera_fits(problem, sol, states)
    lay = problem.layout
    J = sol.jacobian.copy()
    o = 0
    for p, sc in zip(problem.problems, scales):
        n = p.selections[0].n_residuals
        J[o : o + n] /= math.sqrt(sc)
        o += n
    cov, undet6 = covariance_from_jacobian(J, 1.0)
    cov = cov + _limb(problem, sol, states)
    undetermined = tuple(STATE_NAMES[PARAM_NAMES.index(u)] for u in undet6)
    names = list(STATE_NAMES) + [f"clock_offset_s:{c.name}" for c, i in zip(lay.cameras, lay.offset_index) if i is not None]
    names += [f"edge_bias_px:{c.name}" for c, i in zip(lay.cameras, lay.bias_index) if i is not None]
    for k, f in enumerate(fits):
        i = lay.offset_index[k]
        if i is not None:
            fits[k] = JointCameraFit(**{**f.__dict__, "clock_offset_sigma_s": float(math.sqrt(max(cov[i, i], 0.0)))})
    ref = next((k for k, c in enumerate(lay.cameras) if c.clock_offset_s is not None), 0)
    x = sol.x
    t_c, X, V, Jw, _ = world_crossing(x[:6], lay.cameras[ref].camera, lay.t_ref_s, lay.gravity)
    cov7 = Jw @ cov[:6, :6] @ Jw.T
    for name in undetermined:
        i = 1 + STATE_NAMES.index(name)
        cov7[i, :] = np.nan
        cov7[:, i] = np.nan
    if _crossing_moves(Jw[0], undetermined):
        # the crossing time moves with them too: its row is unknown
        cov7[0, :] = np.nan
        cov7[:, 0] = np.nan
    r = sol.residuals
    m = r.size
    dof = m - lay.n_params - sum(p.selections[0].n_groups for p in problem.problems)
    motion = WorldMotion(start.radius_m, float(t_c), tuple(X), tuple(V), tuple(lay.gravity))
    return JointResult(
        motion=motion,
        covariance=cov7,
        parameter_names=tuple(names),
        parameter_covariance=cov,
        cameras=tuple(fits),
        chi2_red=float(r @ r / dof) if dof > 0 else math.nan,
        converged=sol.converged,
        message=sol.message,
        undetermined=undetermined,
        constraint=constraint,
        constraint_residuals=None if constraint is None else r[m - constraint.n_residuals :],
        n_iterations=n_eval,
        run_time_s=time.perf_counter() - t0,
    )


def _crossing_moves(dt_dstate: np.ndarray, undetermined: tuple[str, ...]) -> bool:
    """Whether the crossing time depends on an undetermined state component.

    ``dt_dstate`` is the crossing time's derivative by ``(P, V)`` (s/m,
    s^2/m, :func:`ballscan.geometry.rig.world_crossing`); a component counts
    where its derivative exceeds 1e-9 of the largest of its kind (position
    or velocity): a pose's rounding leaves the plane's normal a few 1e-16
    off an axis.
    """
    for name in undetermined:
        k = STATE_NAMES.index(name)
        kind = dt_dstate[:3] if k < 3 else dt_dstate[3:6]
        if abs(dt_dstate[k]) > 1e-9 * float(np.max(np.abs(kind))):
            return True
    return False
