"""Covariance of the fitted parameters and its propagation to speed, direction and the world frame.

The refinement (Zhao & Wen, Eq. (7)-(10)) fits ``theta = (t_c, y0, z0, vx,
vy, vz)`` of the dynamic sphere (Eq. (8)); its covariance is ``cov = (J^T
J)^-1 * s`` with ``J`` the Jacobian of the whitened residuals at the
solution (:func:`covariance_from_jacobian`) and ``s = max(max(1, chi2_red)
* (1 + rho) / (1 - rho), block)`` (:func:`residual_scale`): the reduced
chi-square when it exceeds 1, the lag-one autocorrelation ``rho`` of the
edge residuals along each side when it is significant, and the variance
ratio of block means of the residuals.  Texture and shading errors are
correlated over many lines; a fit that treated them as independent would
report too small a sigma.  The part of such an error that the motion
absorbs leaves no residual at all (a trend of the edges along the passage
is a ``vy`` or a ``vz``): :func:`limb_covariance` adds it from a model of
the limb's error.  :func:`propagate` carries the covariance to the
speed (with the second-order term of ``|V|``: ``vz`` of a ball crossing the
viewing plane is its weakest parameter, and its uncertainty biases ``|V|``
upwards), the direction and the world frame.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..compiled import as_arg
from ._fit_kernels import block_ratio
from ..geometry.camera import LineScanCamera
from ..geometry.motion import PARAM_NAMES, BallMotion
from .derived import GH_NODES, GH_WEIGHTS, direction_sigmas

__all__ = [
    "LimbSide", "MotionUncertainty", "covariance_from_jacobian", "edge_sides", "limb_covariance", "param_scale", "propagate",
    "projected", "residual_scale", "sight_axes", "significant_square", "smooth_residual_px", "unfixed_across_sight", "unfixed_parameters",
]

#: a velocity component whose 1-sigma exceeds this many times the speed
#: across the viewing plane leaves the flight's direction open by more than
#: +-70 degrees in that component: the image does not fix it
MAX_VELOCITY_SIGMA_RATIO = 3.0

#: a velocity component in the covariance's eigenbasis enters the speed by
#: its square less its variance (:func:`significant_square`) in full where
#: that square exceeds the second of these many variances, not at all below
#: the first, in proportion between (the speed stays continuous in the
#: measurement).  One camera's depth velocity is mostly far below its own
#: sigma, and a component that noise alone lifts above one variance would
#: raise the speed by that noise; a depth velocity from 1.7 sigma on enters
#: whole (docs/benchmarks.md, "One camera's speed: the depth velocity where
#: it stands out of its noise")
SPEED_COMPONENT_VARIANCES = (2.0, 3.0)


def param_scale(camera: LineScanCamera, motion: BallMotion) -> np.ndarray:
    """Natural sizes of ``(t_c, y0, z0, vx, vy, vz)``: one line period, one
    pixel's footprint at the ball (metres), and 0.1 % of the speed (m/s)."""
    z = max(abs(motion.position_m[2]), 1e-3)
    v = max(motion.speed_mps, 1e-6)
    px_m = z / camera.focal_px
    return np.array([1.0 / camera.line_rate_hz, px_m, px_m, 1e-3 * v, 1e-3 * v, 1e-3 * v])


def covariance_from_jacobian(J: np.ndarray, scale: float) -> tuple[np.ndarray, tuple[str, ...]]:
    """Covariance ``(J^T J)^-1 * scale`` of the parameters from the whitened Jacobian ``J`` (M, p).

    The normal matrix is column-equilibrated (the parameters' sizes differ
    by 1e8) before the rank test and the inverse: eigenvalues below 1e-10
    of the largest are dropped, and the parameters of :data:`PARAM_NAMES`
    with more than 1e-3 of their weight on the dropped directions are
    undetermined.

    Returns
    -------
    cov : ndarray (p, p)
        Covariance in the parameters' units (s, m, m/s, ...), the undetermined
        directions left out (not yet NaN).
    undetermined : tuple of str
        Names of the undetermined parameters among the first six.
    """
    cn = np.linalg.norm(J, axis=0)
    cn = np.where(cn > 0, cn, 1.0)
    N = (J / cn).T @ (J / cn)
    evals, evecs = np.linalg.eigh(N)
    undetermined: list[str] = []
    tiny = evals < 1e-10 * max(evals.max(), 1e-300)
    if np.any(tiny):
        weight = (evecs[:, tiny] ** 2).sum(axis=1)
        undetermined = [PARAM_NAMES[k] for k in range(6) if weight[k] > 1e-3]
    inv_evals = np.where(tiny, 0.0, 1.0 / np.where(tiny, 1.0, evals))
    cov_s = (evecs * inv_evals) @ evecs.T
    return cov_s / np.outer(cn, cn) * scale, tuple(undetermined)


@dataclass(frozen=True)
class LimbSide:
    """One side's edges in a fit, for :func:`limb_covariance`.

    Attributes
    ----------
    rows : ndarray of int
        Indices of its edge rows in the fit's stacked residuals (line order).
    t_s : ndarray
        Their lines' times, s.
    sigma_px : ndarray
        The 1-sigma that whitens those rows of the Jacobian, pixels.
    smooth_px : float
        The side's slowly varying residual, pixels (:func:`smooth_residual_px`).
    """

    rows: np.ndarray
    t_s: np.ndarray
    sigma_px: np.ndarray
    smooth_px: float


def limb_covariance(
    J: np.ndarray, cov_unit: np.ndarray, sides, offset_sigma_px: float, trend_sigma_px: float, residual_gain: float
) -> np.ndarray:
    """Covariance of the parameters due to a limb model error of each side that the residuals cannot show.

    Each side's measured edges are taken as displaced by
    ``a + b tau + c P2(tau)`` (pixels), ``tau`` running from -1 to 1 over
    that side's lines and ``P2(tau) = (3 tau^2 - 1) / 2``, with
    ``a ~ N(0, offset_sigma_px^2)`` and ``b, c ~ N(0, s_b^2)`` independent
    per side, ``s_b^2 = trend_sigma_px^2 + (residual_gain * smooth_px)^2``:
    a limb whose model error shows in the residuals hides a larger part in
    the motion.  A trend is absorbed by ``vy`` and the size's change
    (``vz``); a curvature (the passage's ends displaced against its
    middle, as by a shaded cap's edges inside the limb) by the passage's
    duration and the outline's curvature, ``vx`` and ``z0``.  The fit moves
    by ``dx = -(J^T J)^-1 J^T D k`` (``D`` the whitened residuals' change
    per unit of ``k = (a, b, c)``), so the added covariance is
    ``G diag(sigma^2) G^T`` with ``G = (J^T J)^-1 J^T D``.  Rows not named
    by a side (areas, pixels) see no displacement.

    Parameters
    ----------
    J : ndarray (M, p)
        Whitened Jacobian of the residuals at the solution, per parameter unit.
    cov_unit : ndarray (p, p)
        ``(J^T J)^-1`` (pseudo-inverse) of that ``J``.
    sides : sequence of LimbSide
        Each side of each block (camera).
    offset_sigma_px, trend_sigma_px : float
        1-sigma of ``a`` and the least of ``b`` and ``c``, pixels.
    residual_gain : float
        ``b``'s and ``c``'s sigma per pixel of the side's slowly varying residual.

    Returns
    -------
    ndarray (p, p)
    """
    p = J.shape[1]
    cols, sig2 = [], []
    for side in sides:
        if len(side.rows) == 0:
            continue
        t = side.t_s
        span = float(t.max() - t.min())
        tau = 2.0 * (t - t.min()) / span - 1.0 if span > 0 else np.zeros_like(t)
        # J^T D for this side's three columns of D (-1, -tau and -P2(tau), each over sigma, on its rows)
        Jw = J[side.rows] / side.sigma_px[:, None]
        cols += [-Jw.sum(axis=0), -(tau @ Jw), -((1.5 * tau**2 - 0.5) @ Jw)]
        s_b2 = trend_sigma_px**2 + (residual_gain * side.smooth_px) ** 2
        sig2 += [offset_sigma_px**2, s_b2, s_b2]
    if not cols or not any(sig2):
        return np.zeros((p, p))
    G = cov_unit @ np.column_stack(cols)
    return (G * np.asarray(sig2)) @ G.T


def edge_sides(sels, t_s, r: np.ndarray) -> list[LimbSide]:
    """The :class:`LimbSide` of each block's left and right edges in a fit's stacked residuals.

    Parameters
    ----------
    sels : sequence of Selection
        The blocks' selections (:class:`ballscan.solve.problem.Selection`),
        in the order their residuals are stacked (each: left edges, right
        edges, areas, pixels, gains).
    t_s : sequence of ndarray
        Each block's line times, s.
    r : ndarray (M,)
        The fit's whitened residuals at its solution.

    Returns
    -------
    list of LimbSide
        Left then right side of each block.
    """
    sides = []
    o = 0
    for sel, t in zip(sels, t_s):
        for use, sig, n, at in ((sel.use_left, sel.sigma_left, sel.n_left, o), (sel.use_right, sel.sigma_right, sel.n_right, o + sel.n_left)):
            rows = np.arange(at, at + n)
            sides.append(LimbSide(rows, t[use], sig, smooth_residual_px(r[rows], sig)))
        o += sel.n_residuals
    return sides


def smooth_residual_px(r: np.ndarray, sigma_px: np.ndarray, block: int = 8) -> float:
    """RMS of one side's residual over runs of ``block`` residuals beyond what its noise gives, pixels.

    ``r`` are the side's whitened residuals in line order (lines left out
    of the fit leave no gap) and ``sigma_px`` their 1-sigma.  White noise of
    the side's variance ``v = max(1, mean(r^2))`` gives block means of mean
    square ``v / block``, which reaches ``(1 + 3 sqrt(2 / n)) v / block``
    over ``n`` blocks at 3 of its standard deviations (as :func:`block_scale`
    counts a ratio); the excess over that, in pixels by the side's median
    sigma.  0 for fewer than 2 blocks.
    """
    nb = r.size // block
    if nb < 2:
        return 0.0
    m = r[: nb * block].reshape(nb, block).mean(axis=1)
    v = max(1.0, float(np.mean(r * r)))
    excess = float(np.mean(m * m)) - (1.0 + 3.0 * math.sqrt(2.0 / nb)) * v / block
    return math.sqrt(max(excess, 0.0)) * float(np.median(sigma_px))


def unfixed_parameters(cov: np.ndarray, scale_motion: BallMotion) -> tuple[str, ...]:
    """Parameters of :data:`PARAM_NAMES` that a full-rank fit still does not fix: 1-sigma beyond the scale the ball sets.

    The rank test of :func:`covariance_from_jacobian` finds the directions
    the residuals do not see at all; a ball of which the image shows a
    small part (cut by the sensor's or the image's end) has directions they
    see so weakly that the linearised 1-sigma exceeds the parameter's own
    scale, and the fit then finds no minimum along them either (it may
    stop anywhere along them).  The scales come from ``scale_motion``, a
    motion taken from the image without the fit (the key-point guess of
    Eq. (3)-(7), whose ``V.x`` is ``2 R / T``), so that a fit that wandered
    along a weak direction does not widen them: ``t_c``, the time the ball
    takes to cross the viewing plane (``2 R / |vx|``); ``y0`` and ``z0``,
    the distance ``z0``; each velocity component,
    :data:`MAX_VELOCITY_SIGMA_RATIO` times the speed across the plane
    ``|(vx, vy)|``.  NaN sigmas (undetermined by rank) count too.

    Parameters
    ----------
    cov : ndarray (6, 6)
        Covariance of ``(t_c, y0, z0, vx, vy, vz)`` (s, m, m, m/s).
    scale_motion : BallMotion
        The motion the scales are taken from.
    """
    sig = np.sqrt(np.abs(np.diag(np.asarray(cov, dtype=float))[:6]))
    vx, vy, _ = scale_motion.velocity_mps
    vt = math.hypot(vx, vy)
    z0 = abs(scale_motion.position_m[2])
    t_cross = 2.0 * scale_motion.radius_m / abs(vx) if vx != 0 else math.inf
    scale = np.array([t_cross, z0, z0] + [MAX_VELOCITY_SIGMA_RATIO * vt] * 3)
    return tuple(PARAM_NAMES[k] for k in range(6) if not sig[k] <= scale[k])


def sight_axes(position_m) -> tuple[np.ndarray, np.ndarray]:
    """Unit vectors across and along one camera's line of sight to a centre ``(0, y0, z0)``.

    Both lie in the viewing plane: along is ``(0, y0, z0) / r``, across is
    ``(0, z0, -y0) / r`` (``r = |(y0, z0)|``; ``(0, 1, 0)`` on the optical
    axis in front of the camera, ``z0 > 0``).  One camera sees the velocity
    across it as the centre's angular rate and the one along it only as a
    change of the ball's size (:class:`ballscan.solve.derived.Transverse`).

    Parameters
    ----------
    position_m : (3,) array-like
        The centre at ``t_c``, camera frame, metres; not at the camera.

    Returns
    -------
    across, along : ndarray (3,)
        Unit vectors, camera frame.
    """
    _, y0, z0 = (float(c) for c in position_m)
    r = math.hypot(y0, z0)
    if not (math.isfinite(r) and r > 0):
        raise ValueError(f"sight_axes: a centre off the camera, got {tuple(position_m)!r}")
    return np.array([0.0, z0 / r, -y0 / r]), np.array([0.0, y0 / r, z0 / r])


def projected(P: np.ndarray, C: np.ndarray) -> np.ndarray:
    """``P C P^T`` over the components ``P`` weighs: a NaN row of a component with zero weight stays out.

    Parameters
    ----------
    P : ndarray (k, n)
        The linear map.
    C : ndarray (n, n)
        A covariance (NaN rows for undetermined components).
    """
    used = np.flatnonzero(np.any(P != 0.0, axis=0))
    Pu = P[:, used]
    return Pu @ np.asarray(C, dtype=float)[np.ix_(used, used)] @ Pu.T


def unfixed_across_sight(cov: np.ndarray, scale_motion: BallMotion, position_m) -> tuple[str, ...]:
    """Which of ``vx`` and the velocity across the line of sight a fit leaves unfixed, by :func:`unfixed_parameters`' velocity scale.

    Off the optical axis the weak direction of one camera, the velocity
    along its line of sight (:func:`sight_axes`), has a part in ``vy`` as
    well as in ``vz``: both may then exceed their scale while ``vx`` and
    the velocity across the line of sight are fixed.

    Parameters
    ----------
    cov : ndarray (6, 6)
        Covariance of ``(t_c, y0, z0, vx, vy, vz)`` (s, m, m, m/s).
    scale_motion : BallMotion
        The motion the scale is taken from (the key-point guess).
    position_m : (3,) array-like
        The fitted centre at ``t_c``, metres.

    Returns
    -------
    tuple of str
        Among ``("vx_mps", "v_across_mps")``; a NaN sigma counts.
    """
    across, _ = sight_axes(position_m)
    C = np.asarray(cov, dtype=float)[3:6, 3:6]
    var = [projected(np.array([[1.0, 0.0, 0.0]]), C)[0, 0], projected(across[None, :], C)[0, 0]]
    vx, vy, _ = scale_motion.velocity_mps
    scale = MAX_VELOCITY_SIGMA_RATIO * math.hypot(vx, vy)
    return tuple(name for name, v in zip(("vx_mps", "v_across_mps"), var) if not math.sqrt(abs(v)) <= scale)


def residual_scale(chi2_red: float, sides: tuple[np.ndarray, ...], correlated: bool) -> tuple[float, float]:
    """Covariance scale ``s`` for the reduced chi-square and correlated edge residuals.

    Parameters
    ----------
    chi2_red : float
        Reduced chi-square of the fit (NaN counts as 1).
    sides : tuple of ndarray
        Whitened edge residuals, one array per side (and camera) in line order.
    correlated : bool
        Apply the correlation terms (``FitSettings.correlation_inflation``):
        ``(1 + rho) / (1 - rho)`` (at most 10), ``rho`` the largest lag-one
        autocorrelation of a side less ``2 / sqrt(n)`` (what white noise
        reaches by chance), and at least the block-mean variance ratio
        (:func:`block_scale`).

    Returns
    -------
    scale : float
        ``max(max(1, chi2_red) * (1 + rho) / (1 - rho), block)``.
    inflation : float
        ``scale / max(1, chi2_red)``: the part due to correlation.
    """
    inflation = 1.0
    block = 1.0
    if correlated:
        # only a significant correlation (2 sigma of white noise's rho) counts
        rho = max([lag_one(r) - 2.0 / math.sqrt(max(r.size, 1)) for r in sides] + [0.0])
        inflation = min((1.0 + rho) / (1.0 - rho), 10.0) if rho > 0 else 1.0
        block = block_scale(*sides)
    chi_scale = max(1.0, chi2_red if np.isfinite(chi2_red) else 1.0)
    total = max(chi_scale * inflation, block)
    return total, total / chi_scale


def block_scale(*sides: np.ndarray, sizes=(4, 8, 16)) -> float:
    """Variance ratio of block means of whitened residuals (1 for white noise).

    For each side (residuals in line order) and block size ``B``, the mean of
    ``B * mean_block^2`` is what a slowly varying bias inflates (a seam or a
    shading error over a few lines); ratios within the 3-sigma spread of
    white noise (``1 + 3 sqrt(2 / n_blocks)``) count as 1.  Returns the
    largest ratio, at most 100.
    """
    # one compiled pass per side (numpy's summation order)
    best = 1.0
    for r in sides:
        best = max(best, block_ratio(as_arg(r), tuple(int(B) for B in sizes)))
    return min(best, 100.0)


def lag_one(r: np.ndarray) -> float:
    """Lag-one autocorrelation of a residual sequence (0 for fewer than 3)."""
    if r.size < 3:
        return 0.0
    d = r - r.mean()
    den = float(d @ d)
    return float(d[:-1] @ d[1:]) / den if den > 0 else 0.0



# ------------------------------------------------------------- propagation


@dataclass(frozen=True)
class MotionUncertainty:
    """Derived quantities and their 1-sigma from a 6x6 covariance.

    Attributes
    ----------
    speed_mps, speed_sigma_mps : float
        The speed, corrected for the upward bias of the norm of a noisy
        vector, and the RMS of its error, m/s (so ``speed_mps`` is not
        ``|velocity_mps|``).  In the eigenbasis of the velocity covariance
        ``C_v = Q diag(lambda) Q^T`` with ``a = Q^T V``,
        ``speed^2`` is the sum of :func:`significant_square` of the ``a_k``:
        ``a_k^2 - lambda_k``, which estimates the true ``(Q^T V_true)_k^2``
        without bias, where ``a_k^2`` exceeds the second of
        :data:`SPEED_COMPONENT_VARIANCES` variances, 0 below the first and a
        part between (one camera's depth velocity, mostly far below its
        sigma, would otherwise raise the speed by its noise alone).  Only the
        poorly determined direction (chiefly ``vz``) is changed noticeably;
        where its true component is about its own sigma the corrected speed
        may read it as noise and fall short (the reference serve's estimate:
        -0.8 % with ``sigma_vz`` 10 m/s on ``vz`` -5.5 m/s).  The sigma is linear in the
        two well-determined directions plus, for the weakest one, the RMS
        distance of the corrected speed to the speeds whose weak component
        lies about its corrected value within its sigma (24-node
        Gauss-Hermite): not only the linear term when the measured component
        is near 0 while the truth may lie a sigma out.  Where the weak
        direction dominates it overstates the RMS error (up to 2.0x in a
        test, 3-sigma coverage 0.98-1.00).
    speed_raw_mps : float
        ``|V|`` of the estimated velocity (biased upward by about
        ``speed_correction_mps``).
    speed_correction_mps : float
        ``speed_raw_mps - speed_mps``, the bias correction applied, m/s.
    position_m, position_sigma_m : ndarray (3,)
        Centre at ``t_c`` and 1-sigma (x is 0 by definition, sigma 0).
    velocity_mps, velocity_sigma_mps : ndarray (3,)
    direction_deg, direction_sigma_deg : ndarray (2,)
        ``psi_y = atan2(vy, vx)`` and ``psi_z = atan2(vz, vx)``, degrees;
        the sigmas integrated over the velocity's covariance
        (:func:`ballscan.solve.derived.direction_sigmas`).
    world_position_m, world_position_sigma_m, world_velocity_mps, world_velocity_sigma_mps : ndarray or None
        The same in the world frame (``camera.camera_to_world`` /
        ``vectors_to_world``) when the camera has a pose.
    """

    speed_mps: float
    speed_sigma_mps: float
    speed_correction_mps: float
    speed_raw_mps: float
    position_m: np.ndarray
    position_sigma_m: np.ndarray
    velocity_mps: np.ndarray
    velocity_sigma_mps: np.ndarray
    direction_deg: np.ndarray
    direction_sigma_deg: np.ndarray
    world_position_m: np.ndarray | None = None
    world_position_sigma_m: np.ndarray | None = None
    world_velocity_mps: np.ndarray | None = None
    world_velocity_sigma_mps: np.ndarray | None = None


def significant_square(a: np.ndarray, lam) -> np.ndarray:
    """Each velocity component's square less the bias of its noise, in the measure the component stands out of that noise.

    Parameters
    ----------
    a : ndarray
        Measured components (m/s), e.g. in the velocity covariance's eigenbasis.
    lam : float or ndarray
        Their variances, (m/s)^2.

    Returns
    -------
    ndarray
        ``max(a^2 - lambda, 0) * w``, (m/s)^2, with ``w`` rising linearly
        from 0 to 1 as ``a^2 / lambda`` goes from the first to the second
        of :data:`SPEED_COMPONENT_VARIANCES` (``w = 1`` where ``lambda <=
        0``); NaN where ``a`` or ``lambda`` is.
    """
    lo, hi = SPEED_COMPONENT_VARIANCES
    sq = np.square(np.asarray(a, dtype=float))
    lam = np.asarray(lam, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        w = np.where(lam <= 0.0, 1.0, np.clip((sq / lam - lo) / (hi - lo), 0.0, 1.0))
        return np.maximum(sq - lam, 0.0) * w


def _debiased_speed(V: np.ndarray, Cv: np.ndarray, at_truth: bool = False) -> tuple[float, float]:
    """Bias-corrected speed and its mean squared error (see :class:`MotionUncertainty`).

    In the eigenbasis of ``Cv`` each ``a_k^2 - lambda_k`` estimates the true
    ``a_k^2`` without bias; a measured speed takes it in the measure the
    component stands out of its noise (:func:`significant_square`).  The error of
    the well-determined directions is linear (``sum (a_k / s)^2 lambda_k``);
    that of the weakest direction is not (its noise can exceed its value), so
    its mean squared error is integrated over ``a ~ N(mu, lambda)``
    (Gauss-Hermite, 24 nodes).  For a measured ``V``, ``mu^2`` is the
    unbiased plug-in estimate ``max(a^2 - lambda, 0)`` and ``a`` a true
    component the measurement allows: the integral is the squared distance
    of this speed to the true speeds with those ``a``.  With ``at_truth``
    (``V`` the true velocity) ``mu = a`` and ``a`` a new measurement: the
    error this estimator makes on a measurement of covariance ``Cv``, e.g.
    for a bound.

    Returns ``(speed, mse)``: the corrected speed of ``V`` (``|V|`` with
    ``at_truth``) and the mean squared error, (m/s, (m/s)^2).
    """
    lam, Q = np.linalg.eigh(Cv)
    lam = np.maximum(lam, 0.0)
    a = Q.T @ V
    sq = a * a if at_truth else np.maximum(a * a - lam, 0.0)
    kept = sq if at_truth else significant_square(a, lam)
    speed = float(np.sqrt(kept.sum()))
    w = int(np.argmax(lam))
    strong = np.arange(3) != w
    # the true speeds the measurement allows: its unbiased squares (a strong
    # component that significant_square leaves out differs by its variance only)
    s_strong2 = float(sq[strong].sum())
    # d speed / d a_k = a_k / speed; where the correction removed (nearly)
    # everything the derivative is taken at the uncorrected strong part, and
    # with no signal at all the noise's total is the error's scale
    denom = max(speed * speed, float(np.sum(a[strong] ** 2)))
    if denom <= 0.0:
        return speed, float(np.sum(lam))
    var_strong = float(np.sum(a[strong] ** 2 * lam[strong])) / denom
    mu = math.sqrt(sq[w])
    draws = mu + math.sqrt(lam[w]) * GH_NODES
    if at_truth:
        # the estimator's error over new measurements of the truth mu
        est = np.sqrt(s_strong2 + significant_square(draws, lam[w]))
        mse_weak = float(GH_WEIGHTS @ (est - math.sqrt(s_strong2 + mu * mu)) ** 2)
    else:
        # this estimate's distance to the true speeds that the measurement
        # allows (weak component about mu within its sigma): taken at mu
        # alone, a measured component near 0 would claim the speed to the
        # linear term although the truth may lie a sigma out (a table-tennis
        # scene: errors of 4 sigma in 15 % of the noisy renders)
        mse_weak = float(GH_WEIGHTS @ (speed - np.sqrt(s_strong2 + draws * draws)) ** 2)
    return speed, var_strong + mse_weak


def propagate(camera: LineScanCamera, motion: BallMotion, covariance: np.ndarray, at_truth: bool = False) -> MotionUncertainty:
    """Propagate the parameter covariance to speed, direction and world frame.

    Position, velocity, direction and the world frame by linear (first-order)
    propagation ``J C J^T``; the speed by :func:`_debiased_speed` (see
    :class:`MotionUncertainty`).  NaN entries of ``covariance`` propagate to
    NaN.  ``at_truth``: ``motion`` is the true motion and ``covariance`` that
    of a measurement of it (a bound): the speed's sigma is then the RMS error
    of the corrected speed of such a measurement about ``|V|``.
    """
    C = np.asarray(covariance, dtype=float)
    if C.shape != (6, 6):
        raise ValueError(f"covariance: expected (6, 6), got {C.shape}")
    V = np.asarray(motion.velocity_mps)
    Cv = C[3:, 3:]
    raw = float(np.linalg.norm(V))
    g = V / raw if raw > 0 else np.zeros(3)
    var_lin = float(g @ Cv @ g)
    if np.all(np.isfinite(Cv)) and raw > 0:
        speed, var_s = _debiased_speed(V, Cv, at_truth)
    else:
        speed, var_s = raw, var_lin
    # position (0, y0, z0): x is exact by definition of t_c
    Cp = np.zeros((3, 3))
    Cp[1:, 1:] = C[1:3, 1:3]
    out = dict(
        speed_mps=speed,
        speed_sigma_mps=math.sqrt(var_s) if var_s >= 0 else math.nan,
        speed_correction_mps=raw - speed,
        speed_raw_mps=raw,
        position_m=np.asarray(motion.position_m),
        position_sigma_m=np.sqrt(np.diag(Cp)),
        velocity_mps=V,
        velocity_sigma_mps=np.sqrt(np.diag(Cv)),
        direction_deg=np.degrees([math.atan2(V[1], V[0]), math.atan2(V[2], V[0])]),
        direction_sigma_deg=np.degrees(direction_sigmas(V, Cv)),
    )
    if camera.has_pose:
        Rm = camera.rotation_matrix
        out["world_position_m"] = camera.camera_to_world(np.asarray(motion.position_m))
        out["world_position_sigma_m"] = np.sqrt(np.diag(Rm.T @ Cp @ Rm))
        out["world_velocity_mps"] = camera.vectors_to_world(V)
        out["world_velocity_sigma_mps"] = np.sqrt(np.diag(Rm.T @ Cv @ Rm))
    return MotionUncertainty(**out)

