"""Cramér–Rao lower bounds on the ball's position and velocity.

Two kinds of bound are provided:

:func:`edge_crlb`
    Fisher information of the *edge measurements* under the fit's own model
    and weights, ``F = J^T W J`` (:func:`ballscan.solve.problem.whitened_jacobian`):
    the best any unbiased estimator using these edges can do, and what
    :func:`ballscan.solve.fit.fit_motion` should reach with edges of the stated noise.
:func:`pixel_crlb`
    Fisher information of the *pixel intensities* of an untextured, flat
    ball under the averaged coverage model,
    ``I_ij = bg + contrast * coverage_ij(theta) + N(0, sigma_dn^2)``, with
    ``coverage_ij`` the exposure- and pixel-height-averaged overlap of the
    ball's segment with pixel ``j`` of line ``i``.  This bounds every
    estimator working on the image, whatever its edge detector.
    :func:`sensor_crlb` is the same with a sensor's read, shot and
    quantisation noise; :func:`image_crlb` gives each pixel the contrast
    the ball's noise-free image shows there (a shaded or textured ball's
    limb is not its centre).

All return a :class:`PrecisionBound` with 1-sigma bounds on ``t_c``, the
centre at ``t_c``, the velocity, the speed and the direction, and the
quartiles of the speed's absolute error that an efficient estimate reaches
(:func:`speed_error_quantiles`).  The speed's error is not Gaussian where
the depth velocity ``vz`` is poorly determined (a ball crossing the viewing
plane): the bias-corrected norm turns ``vz``'s noise into a one-sided,
heavy-tailed error, so its RMS (``speed_sigma_mps``) says little about its
median.  A median |error| is compared with the bound's median
(``speed_abs_error_quartiles_mps[1]``), an RMS with ``speed_sigma_mps``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from statistics import NormalDist

import numpy as np

from ..geometry.camera import LineScanCamera
from ..model.averaged import averaged_model
from ..model.blur import ALONG_NODES, blur_diameter, semicircle_nodes
from ..model.pixels import pixel_coverage
from .derived import COVARIANCE_PARAMETERS
from .problem import whitened_jacobian
from .settings import FitSettings
from .synthetic import synthetic_edges
from .uncertainty import param_scale, propagate, significant_square
from ..geometry.motion import BallMotion
from ..model.render import SensorNoise
from ..model.silhouette import visible_line_count

__all__ = ["LimbContrast", "PrecisionBound", "edge_crlb", "image_crlb", "limb_contrast", "limb_crlb", "pixel_crlb", "sensor_crlb", "pixel_expectation", "speed_error_quantiles"]


@dataclass(frozen=True)
class PrecisionBound:
    """1-sigma Cramér–Rao bounds.

    Attributes
    ----------
    method : str
        ``"edges"`` or ``"pixels"``.
    motion : BallMotion
        The motion at which the bound is evaluated.
    fisher : ndarray (p, p)
        Fisher information (parameter units of :data:`PARAM_NAMES`, plus the
        edge bias in pixels when it is a nuisance parameter).
    covariance : ndarray (6, 6)
        Inverse Fisher information restricted to the six motion parameters
        (nuisance parameters marginalised).
    t_c_sigma_s : float
    position_sigma_m : ndarray (3,)
        Of the centre at ``t_c`` (x is 0 by definition).
    velocity_sigma_mps : ndarray (3,)
    speed_sigma_mps : float
        RMS error about the true speed of the reported (bias-corrected)
        speed of an efficient velocity estimate (:func:`ballscan.solve.uncertainty.propagate`
        of the bound's covariance with ``at_truth``): not the linearised
        bound alone, which ignores a poorly determined ``vz`` when ``vz = 0``.
    direction_sigma_deg : ndarray (2,)
        Of ``psi_y = atan2(vy, vx)`` and ``psi_z = atan2(vz, vx)``.
    n_measurements : int
        Edges (``"edges"``) or pixels (``"pixels"``) that carry information.
    noise : str
        Description of the noise assumed.
    speed_abs_error_quartiles_mps : ndarray (3,)
        The 25 %, 50 % and 75 % quantiles of the absolute speed error of the
        same efficient estimate (:func:`speed_error_quantiles`), m/s: the
        statistics to set beside an estimator's median and quartiles of
        ``|speed error|``.  Equal to ``0.6745``, ``0.3186`` and ``1.150``
        ``speed_sigma_mps`` only where the speed is linear in the
        velocity's noise; where ``vz`` is the weak axis the median is far
        smaller than ``0.6745 speed_sigma_mps`` (the tail carries the RMS).
    """

    method: str
    motion: BallMotion
    fisher: np.ndarray
    covariance: np.ndarray
    t_c_sigma_s: float
    position_sigma_m: np.ndarray
    velocity_sigma_mps: np.ndarray
    speed_sigma_mps: float
    direction_sigma_deg: np.ndarray
    n_measurements: int
    noise: str
    speed_abs_error_quartiles_mps: np.ndarray = field(default_factory=lambda: np.full(3, np.nan))

    @property
    def sigmas(self) -> np.ndarray:
        """1-sigma of ``(t_c, y0, z0, vx, vy, vz)``."""
        return np.sqrt(np.diag(self.covariance))

    @property
    def speed_median_abs_error_mps(self) -> float:
        """Median ``|speed error|`` of an efficient estimate, m/s (see ``speed_abs_error_quartiles_mps``)."""
        return float(self.speed_abs_error_quartiles_mps[1])

    def to_dict(self) -> dict:
        """The bound as JSON-ready numbers: the motion it is evaluated at, each 1-sigma, and the 6x6 covariance (:data:`ballscan.solve.derived.COVARIANCE_PARAMETERS`)."""
        m = self.motion
        v = np.asarray(m.velocity_mps)

        def num(x):
            x = float(x)
            return x if math.isfinite(x) else None

        return {
            "method": self.method,
            "noise": self.noise,
            "n_measurements": int(self.n_measurements),
            "radius_m": m.radius_m,
            "t_c_s": m.t_c_s,
            "position_m": [num(x) for x in m.position_m],
            "velocity_mps": [num(x) for x in m.velocity_mps],
            "speed_mps": num(m.speed_mps),
            "direction_deg": [math.degrees(math.atan2(v[1], v[0])), math.degrees(math.atan2(v[2], v[0]))],
            "t_c_sigma_s": num(self.t_c_sigma_s),
            "position_sigma_m": [num(x) for x in self.position_sigma_m],
            "velocity_sigma_mps": [num(x) for x in self.velocity_sigma_mps],
            "speed_sigma_mps": num(self.speed_sigma_mps),
            "speed_abs_error_quartiles_mps": [num(x) for x in self.speed_abs_error_quartiles_mps],
            "direction_sigma_deg": [num(x) for x in self.direction_sigma_deg],
            "covariance": {"parameters": list(COVARIANCE_PARAMETERS), "matrix": [[num(x) for x in row] for row in self.covariance]},
        }

    def to_text(self) -> str:
        """A plain-text table of the bounds (units in the header)."""
        m = self.motion
        rows = [
            ("t_c", "s", m.t_c_s, self.t_c_sigma_s),
            ("y0", "m", m.position_m[1], self.position_sigma_m[1]),
            ("z0", "m", m.position_m[2], self.position_sigma_m[2]),
            ("vx", "m/s", m.velocity_mps[0], self.velocity_sigma_mps[0]),
            ("vy", "m/s", m.velocity_mps[1], self.velocity_sigma_mps[1]),
            ("vz", "m/s", m.velocity_mps[2], self.velocity_sigma_mps[2]),
            ("speed", "m/s", m.speed_mps, self.speed_sigma_mps),
        ]
        v = np.asarray(m.velocity_mps)
        rows.append(("psi_y", "deg", math.degrees(math.atan2(v[1], v[0])), self.direction_sigma_deg[0]))
        rows.append(("psi_z", "deg", math.degrees(math.atan2(v[2], v[0])), self.direction_sigma_deg[1]))
        q = self.speed_abs_error_quartiles_mps
        lines = [
            f"Cramér–Rao bound ({self.method}; {self.noise}; {self.n_measurements} measurements; "
            f"an efficient estimate's |speed error|: median {q[1]:.3e} m/s, quartiles {q[0]:.3e}-{q[2]:.3e} m/s)",
            f"{'quantity':<9} {'unit':<5} {'value':>14} {'1-sigma':>12} {'relative':>10}",
        ]
        for name, unit, val, sig in rows:
            rel = f"{abs(sig / val):10.2e}" if val != 0 and np.isfinite(sig) else f"{'-':>10}"
            lines.append(f"{name:<9} {unit:<5} {val:14.6g} {sig:12.3e} {rel}")
        return "\n".join(lines)


def _bound(method: str, motion: BallMotion, camera: LineScanCamera, F: np.ndarray, n_meas: int, noise: str) -> PrecisionBound:
    # Equilibrate before inverting: the parameters' sizes differ by ~1e8.
    d = np.sqrt(np.where(np.diag(F) > 0, np.diag(F), 1.0))
    Fn = F / np.outer(d, d)
    evals = np.linalg.eigvalsh(Fn)
    if evals.min() <= 1e-12 * evals.max():
        cov_full = np.full_like(F, np.inf)
    else:
        cov_full = np.linalg.inv(Fn) / np.outer(d, d)
    cov = cov_full[:6, :6]
    if np.all(np.isfinite(cov)):
        u = propagate(camera, motion, cov, at_truth=True)
        pos, vel, spd, dire = u.position_sigma_m, u.velocity_sigma_mps, u.speed_sigma_mps, u.direction_sigma_deg
        quart = speed_error_quantiles(np.asarray(motion.velocity_mps), cov[3:, 3:], (0.25, 0.5, 0.75))
    else:
        pos, vel, spd, dire = np.full(3, np.inf), np.full(3, np.inf), math.inf, np.full(2, np.inf)
        quart = np.full(3, np.inf)
    return PrecisionBound(
        method=method,
        motion=motion,
        fisher=F,
        covariance=cov,
        t_c_sigma_s=float(math.sqrt(cov[0, 0])),
        position_sigma_m=pos,
        velocity_sigma_mps=vel,
        speed_sigma_mps=float(spd),
        direction_sigma_deg=dire,
        n_measurements=int(n_meas),
        noise=noise,
        speed_abs_error_quartiles_mps=quart,
    )


def speed_error_quantiles(velocity_mps: np.ndarray, velocity_cov: np.ndarray, probs, n_per_axis: int = 64) -> np.ndarray:
    """Quantiles of ``|speed error|`` of an efficient estimate with the bias-corrected speed.

    The velocity estimate is ``V_hat ~ N(V, C_v)``; its speed is the one
    :func:`ballscan.solve.uncertainty.propagate` reports, in the eigenbasis
    ``C_v = Q diag(lambda) Q^T``: the root of the sum of
    :func:`ballscan.solve.uncertainty.significant_square` of ``a = Q^T V_hat``.  The three components of ``a`` are independent
    normals; each is taken at ``n_per_axis`` points, the midpoints of equal
    probability ``(i + 1/2) / n`` of its distribution, and the quantiles are
    those of ``|speed(a) - |V||`` over the ``n^3`` equally weighted
    combinations (deterministic; at the quick Fig. 5 sweep's R = 0.02 m and
    the example golf experiment's z0 = 6 m the quartiles are within 2 % of a
    Monte-Carlo of 2 million draws).

    Parameters
    ----------
    velocity_mps : ndarray (3,)
        True velocity ``V``, m/s.
    velocity_cov : ndarray (3, 3)
        Covariance of the velocity estimate, (m/s)^2.
    probs : sequence of float
        Probabilities in ``[0, 1]``.
    n_per_axis : int
        Points per eigen-direction.

    Returns
    -------
    ndarray
        The quantiles of ``|speed error|``, m/s, one per ``probs``.
    """
    V = np.asarray(velocity_mps, dtype=float)
    C = np.asarray(velocity_cov, dtype=float)
    p = np.asarray(probs, dtype=float)
    if not np.all(np.isfinite(C)):
        return np.full(p.shape, np.inf)
    lam, Q = np.linalg.eigh(C)
    lam = np.maximum(lam, 0.0)
    a = Q.T @ V
    nd = NormalDist()
    z = np.array([nd.inv_cdf((i + 0.5) / n_per_axis) for i in range(n_per_axis)])
    # each axis's squared, corrected component, then their sum over the n^3 grid
    sq = [significant_square(a[k] + math.sqrt(lam[k]) * z, lam[k]) for k in range(3)]
    total = sq[0][:, None, None] + sq[1][None, :, None] + sq[2][None, None, :]
    err = np.abs(np.sqrt(total) - float(np.linalg.norm(V)))
    return np.quantile(err.ravel(), p)


def _n_lines_for(camera: LineScanCamera, motion: BallMotion) -> int:
    t_end = motion.t_c_s + 1.5 * visible_line_count(camera, motion) / camera.line_rate_hz
    return int(math.ceil(t_end * camera.line_rate_hz)) + 3


def edge_crlb(
    camera: LineScanCamera,
    motion: BallMotion,
    edge_noise_px: float,
    *,
    area_noise_px: float | None = None,
    settings: FitSettings = FitSettings(fit_edge_bias=False, edge_floor_px=0.0),
) -> PrecisionBound:
    """Cramér–Rao bound of the edge measurements under the fit's model.

    Parameters
    ----------
    camera : LineScanCamera
    motion : BallMotion
        Radius, ``t_c`` (s), centre at ``t_c`` (m) and velocity (m/s); the
        image is assumed to start at line 0 and to contain the whole ball.
    edge_noise_px : float
        1-sigma of each edge, pixels.
    area_noise_px : float, optional
        1-sigma of an end line's summed coverage, pixels; ``None`` leaves the
        area residuals out (only the fit's edges count, a conservative bound).
    settings : FitSettings
        Residual selection and weights (by default the bare edge noise and
        no edge-bias nuisance; pass the fit's settings to bound the fit).

    Returns
    -------
    PrecisionBound
    """
    if not (edge_noise_px > 0 and math.isfinite(edge_noise_px)):
        raise ValueError(f"edge_noise_px: must be positive and finite, got {edge_noise_px!r}")
    n_lines = _n_lines_for(camera, motion)
    a_sig = area_noise_px if area_noise_px is not None else 1e9
    edges = synthetic_edges(
        camera, motion, n_lines, edge_sigma_px=edge_noise_px, area_sigma_px=a_sig, max_spread_px=settings.max_spread_px, add_noise=False
    )
    J, names = whitened_jacobian(camera, edges, motion, settings)
    F = J.T @ J
    n = int(edges.left_ok.sum() + edges.right_ok.sum())
    noise = f"edge noise {edge_noise_px:g} px" + (f", area noise {area_noise_px:g} px" if area_noise_px is not None else "")
    return _bound("edges", motion, camera, F, n, noise)


def pixel_expectation(
    camera: LineScanCamera, motion: BallMotion, t_s: np.ndarray, cols_px: np.ndarray, n_nodes: int = 8
) -> tuple[np.ndarray, np.ndarray]:
    """Averaged coverage of given pixels by the ball and its derivatives in the motion's parameters.

    The exposure- and pixel-height-averaged overlap (Eq. (1) and (8)
    integrated over the exposure, :func:`ballscan.model.averaged.averaged_model`
    and :func:`ballscan.model.pixels.pixel_coverage`) of the ball's segment
    with pixel ``cols_px[j]`` of the line at ``t_s[i]``, blurred by the
    camera's blur circle (``defocus_px``) across the sensor and along it
    (:func:`ballscan.model.blur.semicircle_nodes`): what the bounds'
    pixel model expects, and what a maximum-likelihood fit of the pixels
    iterates on.  Derivatives by central differences (step ``1e-3`` of
    :func:`ballscan.solve.uncertainty.param_scale`).

    Parameters
    ----------
    camera : LineScanCamera
    motion : BallMotion
    t_s : ndarray (N,)
        Line centre times, seconds.
    cols_px : ndarray (C,)
        Pixel centres, pixels (a unit grid).
    n_nodes : int
        Quadrature nodes per piece of the averaged model.

    Returns
    -------
    coverage : ndarray (N, C)
        0 (background) to 1 (ball); 0 on lines without the ball.
    d_coverage : ndarray (6, N, C)
        Per unit of each parameter of :data:`ballscan.geometry.motion.PARAM_NAMES`.
    """
    t = np.asarray(t_s, dtype=float)
    cols = np.asarray(cols_px, dtype=float)
    theta = motion.to_params()
    h = 1e-3 * param_scale(camera, motion)
    thetas = np.vstack([theta[None], theta + np.diag(h), theta - np.diag(h)])
    ms = averaged_model(camera, thetas, motion.radius_m, t, motion.acceleration_mps2, n_nodes, return_samples=True)
    u_lo, u_hi, wgt = ms.samples  # type: ignore[misc]
    # the blur circle along the sensor: the coverage at its marginal's shifts (the samples carry it across the sensor)
    shifts, weights = semicircle_nodes(blur_diameter(camera), ALONG_NODES)
    # (13, N, C); NaN: a line without the ball
    cov = sum(w * np.nan_to_num(pixel_coverage(u_lo, u_hi, wgt, cols - s)) for s, w in zip(shifts, weights))
    return cov[0], (cov[1:7] - cov[7:]) / (2.0 * h[:, None, None])


def _pixel_model(camera: LineScanCamera, motion: BallMotion, n_nodes: int) -> tuple[np.ndarray, np.ndarray]:
    """:func:`pixel_expectation` on the lines that see the ball and the columns it touches plus two (and the blur circle's radius) on each side.

    Returns ``(coverage, d_coverage)``: ``(N, C)`` and ``(6, N, C)``.
    """
    n_lines = _n_lines_for(camera, motion)
    t = np.arange(n_lines) / camera.line_rate_hz
    theta = motion.to_params()
    me = averaged_model(camera, theta[None], motion.radius_m, t, motion.acceleration_mps2, n_nodes)
    keep = np.flatnonzero(me.presence[0] > 0)
    if keep.size == 0:
        raise ValueError("pixel_crlb: the ball is not seen on any line")
    return pixel_expectation(camera, motion, t[keep], _ball_columns(camera, me, keep).astype(float), n_nodes)


def _ball_columns(camera: LineScanCamera, me, lines: np.ndarray) -> np.ndarray:
    """The columns the averaged model ``me`` touches on ``lines``, with two and the blur circle's radius on either side (not clipped to the sensor)."""
    reach = 2 + math.ceil(0.5 * blur_diameter(camera))
    return np.arange(math.floor(np.nanmin(me.left_px[0, lines])) - reach, math.ceil(np.nanmax(me.right_px[0, lines])) + reach + 1)


def _pixel_fisher(G: np.ndarray, var: np.ndarray, signal: np.ndarray | None = None, prnu_sigma: float = 0.0) -> np.ndarray:
    """Fisher information of independent columns of Gaussian pixels.

    Column ``c`` of the image has the covariance
    ``diag(var[:, c]) + prnu_sigma^2 s_c s_c^T`` with ``s_c = signal[:, c]``:
    white noise plus an unknown gain ``1 + prnu_sigma N(0, 1)`` of the
    column applied to the ball's signal above the column's background (the
    background itself, gain included, is what every line of that column
    without the ball measures).  By the Woodbury identity
    ``F = sum_c G_c^T D_c^-1 G_c - k (G_c^T D_c^-1 s_c)(s_c^T D_c^-1 G_c) / (1 + k s_c^T D_c^-1 s_c)``
    with ``k = prnu_sigma^2``.  The information in the covariance's own
    dependence on the parameters is left out (below 1e-4 of the mean's here).

    Parameters
    ----------
    G : ndarray (p, N, C)
        Derivatives of the pixels' mean, DN per parameter unit.
    var : ndarray (N, C)
        White-noise variance of each pixel, DN^2.
    signal : ndarray (N, C), optional
        The ball's signal above the background that the column gain scales, DN.
    prnu_sigma : float
        Relative 1-sigma of the column gain.
    """
    Gw = G / var
    F = np.einsum("pnc,qnc->pq", Gw, G)
    if prnu_sigma > 0 and signal is not None:
        k = prnu_sigma**2
        u = np.einsum("pnc,nc->pc", Gw, signal)  # G_c^T D^-1 s_c
        q = np.einsum("nc,nc->c", signal / var, signal)  # s_c^T D^-1 s_c
        F = F - (u * (k / (1.0 + k * q))) @ u.T
    return F


def pixel_crlb(
    camera: LineScanCamera,
    motion: BallMotion,
    noise_dn: float,
    contrast_dn: float,
    *,
    prnu_sigma: float = 0.0,
    n_nodes: int = 8,
) -> PrecisionBound:
    """Cramér–Rao bound of the pixel intensities of a flat, untextured ball.

    ``I_ij = bg_j + g_j contrast_dn coverage_ij(theta) + N(0, noise_dn^2)``;
    ``bg_j`` and ``contrast_dn`` are treated as known (they are measured on
    thousands of pixels); the column gain ``g_j = 1 + prnu_sigma N(0, 1)``
    (fixed-pattern photo-response non-uniformity, PRNU) is unknown and
    enters as noise correlated along each column (:func:`_pixel_fisher`).
    The coverage derivatives are central differences of the averaged
    coverage model.

    Parameters
    ----------
    camera : LineScanCamera
    motion : BallMotion
    noise_dn : float
        Gaussian pixel noise, DN (1-sigma).
    contrast_dn : float
        ``|ball - background|``, DN.
    prnu_sigma : float
        Relative 1-sigma of the columns' gain, unknown to the estimator
        (0: a flat-field corrected or ideal sensor).
    n_nodes : int
        Quadrature nodes per piece of the averaged model.

    See Also
    --------
    sensor_crlb : the same with the renderer's full sensor model (shot noise per pixel).
    """
    if not (noise_dn > 0 and math.isfinite(noise_dn)):
        raise ValueError(f"noise_dn: must be positive and finite, got {noise_dn!r}")
    if not (contrast_dn != 0 and math.isfinite(contrast_dn)):
        raise ValueError(f"contrast_dn: must be non-zero and finite, got {contrast_dn!r}")
    _check_prnu(prnu_sigma)
    cov, dcov = _pixel_model(camera, motion, n_nodes)
    G = contrast_dn * dcov
    F = _pixel_fisher(G, np.full(cov.shape, float(noise_dn) ** 2), contrast_dn * cov, prnu_sigma)
    n_pix = int((np.abs(G).sum(axis=0) > 0).sum())
    noise = f"pixel noise {noise_dn:g} DN, contrast {abs(contrast_dn):g} DN" + (f", PRNU {prnu_sigma:g}" if prnu_sigma > 0 else "")
    return _bound("pixels", motion, camera, F, n_pix, noise)


def sensor_crlb(
    camera: LineScanCamera,
    motion: BallMotion,
    noise: SensorNoise,
    ball_level: float,
    background_level: float,
    *,
    flat_field: bool = False,
    n_nodes: int = 8,
) -> PrecisionBound:
    """Cramér–Rao bound of the pixels of a flat ball seen by a modelled sensor.

    The sensor of :class:`ballscan.model.render.SensorNoise`: pixel ``(i, j)`` of
    linear grey ``Y_ij = bg + (ball - bg) coverage_ij(theta)`` has the mean
    ``black + white g_j Y_ij`` DN and the white-noise variance
    ``read^2 + white^2 Y_ij / full_well + 1/12`` DN^2 (read, shot and
    uniform quantisation noise, each pixel its own), and the column gain
    ``g_j = 1 + prnu_sigma N(0, 1)`` is unknown (``flat_field=False``): it
    scales the ball's signal ``white (ball - bg) coverage_ij`` of every
    line of column ``j`` alike, a fixed pattern that does not average out
    over the lines a slow ball's edge spends in one column
    (:func:`_pixel_fisher`).  The background of each column, gain included,
    is treated as known (every line without the ball measures it), as are
    the two levels.

    Parameters
    ----------
    camera : LineScanCamera
    motion : BallMotion
    noise : SensorNoise
    ball_level, background_level : float
        Linear grey of the (flat) ball and of the background, 0..1.
    flat_field : bool
        The column gains are known (a flat-field corrected camera): PRNU
        then costs nothing.
    n_nodes : int
        Quadrature nodes per piece of the averaged model.
    """
    for name, v in (("ball_level", ball_level), ("background_level", background_level)):
        if not (math.isfinite(v) and v >= 0):
            raise ValueError(f"{name}: must be a finite number >= 0, got {v!r}")
    if ball_level == background_level:
        raise ValueError("ball_level: must differ from background_level (no contrast, no bound)")
    cov, dcov = _pixel_model(camera, motion, n_nodes)
    dy = ball_level - background_level
    var = np.broadcast_to(_sensor_variance(noise, background_level + dy * cov), cov.shape)
    prnu = 0.0 if flat_field else noise.prnu_sigma
    G = noise.white_dn * dy * dcov
    F = _pixel_fisher(G, var, noise.white_dn * dy * cov, prnu)
    n_pix = int((np.abs(G).sum(axis=0) > 0).sum())
    fw = f"{noise.full_well_e:g} e-" if noise.full_well_e else "no shot noise"
    desc = (
        f"sensor: read {noise.read_dn:g} DN, {fw}, white {noise.white_dn:g} DN, {noise.bits}-bit, "
        f"PRNU {noise.prnu_sigma:g}" + (" (flat-fielded)" if flat_field else "") + f"; levels {ball_level:g} / {background_level:g}"
    )
    return _bound("pixels", motion, camera, F, n_pix, desc)


@dataclass(frozen=True)
class LimbContrast:
    """Each pixel's contrast around a ball, read off its noise-free image (:func:`limb_contrast`).

    Attributes
    ----------
    lines : ndarray of int (N,)
        The image lines that see the ball.
    cols : ndarray of int (C,)
        The image columns it touches, with the blur circle's radius and two
        pixels on either side.
    contrast : ndarray (N, C)
        What the ball shows at each pixel above the background, linear grey
        (negative where darker).
    background : ndarray (N, C)
        The background at those pixels, linear grey.
    coverage, d_coverage : ndarray (N, C) and (6, N, C)
        The pixels' coverage and its derivatives (:func:`pixel_expectation`).
    """

    lines: np.ndarray
    cols: np.ndarray
    contrast: np.ndarray
    background: np.ndarray
    coverage: np.ndarray
    d_coverage: np.ndarray

    def other_sign_share(self, sign: float) -> float:
        """Share of the limb's information (coverage derivatives squared, summed over the parameters) on pixels whose contrast is not of ``sign``."""
        w = np.square(self.d_coverage).sum(axis=0)
        total = float(w.sum())
        return float(np.sum(w * (np.sign(self.contrast) != np.sign(sign))) / total) if total > 0 else math.nan


def limb_contrast(
    camera: LineScanCamera,
    motion: BallMotion,
    expected: np.ndarray,
    background: np.ndarray,
    t_lines_s: np.ndarray,
    *,
    readable: np.ndarray | None = None,
    min_coverage: float = 0.2,
    n_nodes: int = 8,
) -> LimbContrast:
    """What a ball shows at each of its pixels above the background, read off its noise-free image.

    On the pixels the ball covers by at least ``min_coverage``,
    ``(expected - background) / coverage`` (the coverage of
    :func:`pixel_expectation`, blurred by the camera's blur circle,
    ``camera.defocus_px``, if any); elsewhere the nearest such pixel's of
    the same line, and on a line with none (the ends, crossed in part
    during the exposure) the nearest line's.

    Parameters
    ----------
    camera : LineScanCamera
    motion : BallMotion
        The ball's true motion (the one ``expected`` shows).
    expected : ndarray (n_lines, W)
        The image's noise-free linear grey, 0..1.
    background : ndarray (n_lines, W) or (W,)
        Its linear grey without the ball.
    t_lines_s : ndarray (n_lines,)
        Each line's centre time, seconds.
    readable : ndarray of bool (n_lines, W), optional
        Pixels that may be read (False: another ball's, say); default all.
    min_coverage : float
        Least coverage of a pixel that is read, in (0, 1].
    n_nodes : int
        Quadrature nodes per piece of the averaged model.

    Raises
    ------
    ValueError
        If the arrays' shapes disagree, or the ball is not seen on any
        line, or no pixel of it can be read.
    """
    expected = np.asarray(expected, dtype=float)
    t = np.asarray(t_lines_s, dtype=float)
    if expected.ndim != 2 or expected.shape[1] != camera.width or t.shape != (expected.shape[0],):
        raise ValueError(f"expected: need (n_lines, {camera.width}) with one line time each, got {expected.shape} and {t.shape}")
    background = np.broadcast_to(np.asarray(background, dtype=float), expected.shape)
    readable = np.ones(expected.shape, dtype=bool) if readable is None else np.broadcast_to(np.asarray(readable, dtype=bool), expected.shape)
    if not 0.0 < min_coverage <= 1.0:
        raise ValueError(f"min_coverage: must be in (0, 1], got {min_coverage!r}")
    me = averaged_model(camera, motion.to_params()[None], motion.radius_m, t, motion.acceleration_mps2, n_nodes)
    lines = np.flatnonzero(me.presence[0] > 0)
    if lines.size == 0:
        raise ValueError("limb_contrast: the ball is not seen on any line")
    cols = _ball_columns(camera, me, lines)
    cols = cols[(cols >= 0) & (cols < camera.width)]
    cov, dcov = pixel_expectation(camera, motion, t[lines], cols.astype(float), n_nodes)
    box = np.ix_(lines, cols)
    contrast = _limb_contrast(expected[box] - background[box], cov, readable[box], min_coverage)
    return LimbContrast(lines, cols, contrast, background[box], cov, dcov)


def image_crlb(
    camera: LineScanCamera,
    motion: BallMotion,
    noise: SensorNoise,
    expected: np.ndarray,
    background: np.ndarray,
    t_lines_s: np.ndarray,
    *,
    readable: np.ndarray | None = None,
    flat_field: bool = False,
    min_coverage: float = 0.2,
    n_nodes: int = 8,
) -> PrecisionBound:
    """Cramér–Rao bound of the pixels of a ball whose brightness varies over its surface, read off its noise-free image.

    :func:`sensor_crlb` with each pixel's own contrast: the mean of pixel
    ``(i, j)`` is ``bg_ij + c_ij coverage_ij(theta)`` (linear grey), where
    ``c_ij`` is what the ball shows there above the background
    (:func:`limb_contrast`).  A shaded ball's limb is dimmer (or, for a
    ball darker than the background, darker) than its centre, and a
    textured one's varies with the pattern that reaches it; the edges carry
    the limb's contrast, not the centre's.  The derivatives are ``c_ij``
    times the coverage's: the limb's motion, its contrast held as read.
    The surface pattern's own motion inside the silhouette is left out:
    the figure is the bound of the silhouette's information at the limb's
    contrast, a reference for estimators that measure the silhouette (one
    that knew the pattern could do better).  Only the lines and columns the
    image holds count (a cut ball's visible part), with the camera's blur
    circle.  Noise, column gains and their prior as :func:`sensor_crlb`.

    Parameters
    ----------
    camera, motion, expected, background, t_lines_s, readable, min_coverage, n_nodes
        As for :func:`limb_contrast`.
    noise : SensorNoise
    flat_field : bool
        The column gains are known.

    Raises
    ------
    ValueError
        As :func:`limb_contrast`.
    """
    _check_prnu(noise.prnu_sigma)
    lc = limb_contrast(camera, motion, expected, background, t_lines_s, readable=readable, min_coverage=min_coverage, n_nodes=n_nodes)
    return limb_crlb(camera, motion, noise, lc, flat_field=flat_field)


def limb_crlb(camera: LineScanCamera, motion: BallMotion, noise: SensorNoise, limb: LimbContrast, *, flat_field: bool = False) -> PrecisionBound:
    """The bound of :func:`image_crlb` from a contrast map already read (:func:`limb_contrast` at ``camera`` and ``motion``)."""
    _check_prnu(noise.prnu_sigma)
    prnu = 0.0 if flat_field else noise.prnu_sigma
    signal = limb.contrast * limb.coverage
    G = noise.white_dn * limb.contrast * limb.d_coverage
    F = _pixel_fisher(G, _sensor_variance(noise, limb.background + signal), noise.white_dn * signal, prnu)
    n_pix = int((np.abs(G).sum(axis=0) > 0).sum())
    desc = f"sensor: read {noise.read_dn:g} DN, white {noise.white_dn:g} DN, PRNU {prnu:g}; each pixel's contrast read off the noise-free image"
    return _bound("pixels", motion, camera, F, n_pix, desc)


def _limb_contrast(signal: np.ndarray, cov: np.ndarray, readable: np.ndarray, min_coverage: float) -> np.ndarray:
    """Each pixel's contrast ``signal / cov`` where readable and covered by ``min_coverage``, else its line's nearest such pixel's.

    A line with no such pixel (the ball's first and last lines, which it
    crosses only in part during the exposure) takes the nearest line's.
    """
    ok = readable & (cov >= min_coverage)
    if not ok.any():
        raise ValueError("limb_contrast: no pixel of the ball can be read (coverage or readable)")
    c = np.where(ok, signal / np.where(ok, cov, 1.0), 0.0)
    j = np.arange(c.shape[1])
    rows = np.flatnonzero(ok.any(axis=1))
    for i in rows:
        have = np.flatnonzero(ok[i])
        c[i] = c[i, have[np.abs(j[:, None] - have[None, :]).argmin(axis=1)]]
    empty = np.flatnonzero(~ok.any(axis=1))
    if empty.size:
        c[empty] = c[rows[np.abs(empty[:, None] - rows[None, :]).argmin(axis=1)]]
    return c


def _sensor_variance(noise: SensorNoise, y: np.ndarray) -> np.ndarray:
    """White-noise variance (DN^2) of pixels of linear grey ``y``: read, shot and uniform quantisation noise."""
    y = np.asarray(y, dtype=float)
    shot = y * noise.white_dn**2 / noise.full_well_e if noise.full_well_e else np.zeros_like(y)
    return noise.read_dn**2 + 1.0 / 12.0 + shot


def _check_prnu(prnu_sigma: float) -> None:
    if not (math.isfinite(prnu_sigma) and 0 <= prnu_sigma < 1):
        raise ValueError(f"prnu_sigma: must be in [0, 1), got {prnu_sigma!r}")
