"""Weighted nonlinear least-squares fit of the ball's motion to measured edges.

The model is the averaged silhouette of :mod:`ballscan.model.silhouette` (the
paper's dynamic sphere, first Eq. (8), projected by Eq. (2), averaged over the
pixel's height and the exposure).  It is fitted over the six parameters
``theta = (t_c, y0, z0, vx, vy, vz)`` (:data:`ballscan.geometry.motion.PARAM_NAMES`)
and, optionally (off by default: it trades against ``z0``), a symmetric edge
bias ``b`` (pixels, a "dilation": left edges move by ``-b``, right edges by
``+b``).

Residuals (all whitened by their 1-sigma):

* edge lines: ``left_model - b - left_meas`` and ``right_model + b -
  right_meas`` where the edge is usable; the narrow local-area edges of
  :mod:`ballscan.measure.edges` where the model's edge spread over the exposure and
  pixel height is below ``max_spread_px``, the wide-window edges up to
  ``max_spread_wide_px``.  Each edge's sigma is its pixel noise (signal-
  dependent), a systematic floor and its texture indicator in quadrature;
* area lines: the lines just outside the ball (``area_model - area_meas``,
  so that lines where the model says "absent" but the data shows ball, and
  vice versa, produce residuals) and the ball's end lines, where the chord
  grows like the square root of time: their summed coverage divided by the
  shading model's brightness of the covered part when the edges carry it
  (``area_level``; sigma from the pixel noise and how well that model
  predicts a line's brightness), else with a large relative sigma (the lit
  or shaded cap's brightness is unknown).  The lines the ball enters or
  leaves during the exposure are levelled only when they agree with the
  rest of the fit (:func:`_partial_verdict`: a ball cut by the image's
  first or last line keeps them loose, and so do lines that a renderer's
  few exposure sub-frames put measurably off);
* optionally (``pixels``) the pixels of the spread edges' windows and of
  the end lines instead of their edges and areas (:func:`_pixel_residuals`).

The built-in Levenberg-Marquardt solver (:func:`_levenberg_marquardt`; a
:func:`scipy.optimize.least_squares` path is kept as a cross-check) fits by
least squares, then rejects edges whose residual exceeds
``reject_sigma`` robust sigmas (a seam crossing the limb), re-selects the
residuals at the solution and fits again, at most ``max_reject_rounds``
times.  The Jacobian (:func:`hybrid_jacobian`) is analytic on the lines
well inside the ball's crossing (the chord model's closed-form derivatives,
:func:`chord_jacobian`; the averaged edge differs from the chord edge there
by a small smooth correction whose derivative is below 0.1 % of the
largest term) and a forward difference of a vectorised copy of the
averaged model on the ball's end lines and the area lines (all perturbed
parameter sets in one numpy call; :func:`model_jacobian`, tested against
central differences of :func:`ballscan.model.silhouette.silhouette`).

Covariance
----------
``cov = (J^T J)^-1 * s`` with ``J`` the Jacobian of the whitened residuals at
the solution and ``s = max(max(1, chi2_red) * (1 + rho) / (1 - rho), block)``:
the reduced chi-square when it exceeds 1, the lag-one autocorrelation
``rho`` of the edge residuals along each side when it is significant, and
the variance ratio of block means of the residuals (:func:`_block_scale`).
Texture and shading errors are correlated over many lines; a fit that
treated them as independent would report too small a sigma.  The sigmas are
therefore never smaller than what the pixel noise implies and grow with
the residuals' visible structure.  :func:`propagate` carries the second-
order term of ``|V|`` into the speed's sigma (``vz`` of a ball crossing the
viewing plane is its weakest parameter, and its uncertainty biases ``|V|``
upwards).
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, field, replace

import numpy as np
from scipy.optimize import least_squares
from scipy.special import chdtri

from ..compiled import as_arg
from ..model._forward_kernels import averaged_samples, chord_edges, coverage_grid
from ..model._forward_kernels import pixel_residuals as _kernel_pixel_residuals
from ..model._forward_kernels import pixel_residuals_jacobian as _kernel_pixel_residuals_jacobian
from ._fit_kernels import (
    area_tables, block_ratio, damped, equilibrated, fit_jacobian, fit_residuals, hybrid_rows, loose_rows, on_both_sides, select_lines,
)
from ..geometry.camera import LineScanCamera
from ..measure.detection import median as _median
from ..measure.edges import EdgeMeasurements
from ..geometry.motion import PARAM_NAMES, BallMotion
from ..model.silhouette import _gauss

__all__ = [
    "FitResult",
    "FitSettings",
    "MotionUncertainty",
    "ModelEdges",
    "averaged_model",
    "chord_jacobian",
    "hybrid_jacobian",
    "model_jacobian",
    "param_scale",
    "pixel_coverage",
    "fit_motion",
    "propagate",
    "synthetic_edges",
    "whitened_jacobian",
]

_DILATION = "edge_bias_px"


# ------------------------------------------------------------------- model


@dataclass(frozen=True)
class ModelEdges:
    """Averaged-silhouette predictions for P parameter sets and N lines.

    Attributes
    ----------
    left_px, right_px : ndarray (P, N)
        Mean edges over the present samples, pixels; where the ball is absent
        both equal the projection of the centre (so that the model is
        continuous as a line's presence goes to 0).
    presence : ndarray (P, N)
        Fraction of (exposure x pixel height) samples in which the ball is seen.
    area_px : ndarray (P, N)
        Expected summed pixel coverage, pixels.
    spread_px : ndarray (P, N)
        Weighted standard deviation of the sample edges about their mean
        (the larger of left and right), pixels.
    valid : ndarray (P, N) of bool
        False where an edge ray would point backwards / the camera is inside.
    samples : tuple or None
        ``(u_lo, u_hi, weight)`` per sample, each (P, N, 3, n), when asked for.
    """

    left_px: np.ndarray
    right_px: np.ndarray
    presence: np.ndarray
    area_px: np.ndarray
    spread_px: np.ndarray
    valid: np.ndarray
    samples: tuple[np.ndarray, np.ndarray, np.ndarray] | None = None


def averaged_model(
    camera: LineScanCamera,
    thetas: np.ndarray,
    radius_m: float,
    t_lines_s: np.ndarray,
    acceleration_mps2=(0.0, 0.0, 0.0),
    n_nodes: int = 4,
    return_samples: bool = False,
) -> ModelEdges:
    """Vectorised averaged silhouette for several parameter sets at once.

    Same mathematics as :func:`ballscan.model.silhouette.silhouette` with
    ``model="averaged"`` (see its Notes), broadcast over a leading axis of
    parameter sets ``thetas`` of shape (P, 6) in :data:`PARAM_NAMES` order
    (seconds, metres, m/s).  ``n_nodes = 4`` Gauss-Legendre nodes per piece
    agree with 32 nodes to 1e-8 px on a tennis serve (inner lines are then
    done with 2 nodes, see below); ``n_nodes <= 3`` evaluates every line with
    ``n_nodes`` in one call (3 nodes: 1e-4 px at worst at the ball's ends,
    about twice as fast).
    """
    th = np.atleast_2d(np.asarray(thetas, dtype=float))
    t_all = np.asarray(t_lines_s, dtype=float).reshape(-1)
    if n_nodes <= 3 or return_samples:
        return _model_core(camera, th, float(radius_m), t_all, acceleration_mps2, n_nodes, return_samples)
    # Lines well inside the ball's crossing (|x0| + A + B < 0.9 R for the first
    # parameter set) have smooth edges in the quadrature variable: 2 nodes per
    # piece are exact to 2e-6 px there; the end lines get n_nodes.
    m0 = BallMotion.from_params(th[0], float(radius_m), acceleration_mps2)
    c = m0.centre(t_all)
    vx = np.abs(m0.velocity_at(t_all)[:, 0])
    reach = np.abs(c[:, 0]) + vx * camera.exposure / 2 + np.maximum(c[:, 2], 0.0) / (2 * camera.focal_px)
    inner = reach < 0.9 * float(radius_m)
    if not inner.any() or inner.all():
        return _model_core(camera, th, float(radius_m), t_all, acceleration_mps2, n_nodes if not inner.all() else 2, False)
    a = _model_core(camera, th, float(radius_m), t_all[inner], acceleration_mps2, 2, False)
    b = _model_core(camera, th, float(radius_m), t_all[~inner], acceleration_mps2, n_nodes, False)
    out = {}
    for k in ("left_px", "right_px", "presence", "area_px", "spread_px", "valid"):
        va, vb = getattr(a, k), getattr(b, k)
        arr = np.empty((th.shape[0], t_all.size), dtype=va.dtype)
        arr[:, inner] = va
        arr[:, ~inner] = vb
        out[k] = arr
    return ModelEdges(**out)


def _edges_model(camera, th, R, t, acc, n_nodes) -> ModelEdges:
    """:func:`averaged_model` without the edge spread and validity (``None``), for the fit's inner loop.

    ``t`` of shape (P, N) gives every parameter set its own line times.
    """
    if n_nodes <= 3 or np.ndim(t) == 2:
        return _model_core(camera, th, float(R), t, acc, n_nodes, False, False)
    return averaged_model(camera, th, R, t, acc, n_nodes)


def _model_core(camera, th, R, t_all, acceleration_mps2, n_nodes, return_samples, full: bool = True) -> ModelEdges:
    """The averaged model for parameter sets ``th`` (P, 6) and line times ``t_all`` (N,) or (P, N).

    Per-line quantities are (P, N); the samples (``return_samples``) are
    (P, N, 3, n_nodes): three pieces of ``n_nodes`` Gauss-Legendre nodes
    over the quadrature angle between the kinks of the exposure-and-height
    density.  ``full=False`` skips the edge spread and the validity test
    (``spread_px`` and ``valid`` are then None).  The fit calls it some ten
    times per ball: one compiled loop over the samples
    (:func:`ballscan.model._forward_kernels.averaged_samples`).
    """
    # contiguous and writeable: the kernel's one compiled signature
    th = as_arg(np.atleast_2d(th))
    t = np.asarray(t_all, dtype=float)
    t = as_arg(t if t.ndim == 2 else t.reshape(1, -1))
    if th.shape[1] != 6 or t.shape[0] not in (1, th.shape[0]):
        raise ValueError(f"_model_core: parameter sets {th.shape} and line times {t.shape} do not match")
    left, right, presence, area, spread, valid, u_lo, u_hi, wgt = averaged_samples(
        th, t, *_kernel_args(camera, R, acceleration_mps2, n_nodes), bool(full), bool(return_samples)
    )
    samples = None
    if return_samples:
        shp = left.shape + (3, n_nodes)
        samples = (u_lo.reshape(shp), u_hi.reshape(shp), wgt.reshape(shp))
    return ModelEdges(
        left_px=left,
        right_px=right,
        presence=presence,
        area_px=area,
        spread_px=spread if full else None,
        valid=valid if full else None,
        samples=samples,
    )


def _kernel_args(camera, R, acceleration_mps2, n_nodes) -> tuple:
    """:func:`ballscan.model._forward_kernels.averaged_samples`' arguments after the line times: radius, camera, acceleration, nodes."""
    g, gw = _gauss(n_nodes)
    return (
        float(R), float(camera.exposure), float(camera.focal_px), float(camera.principal_px), float(camera.k1), float(camera.k2),
        np.array([float(a) for a in acceleration_mps2]), as_arg(g), as_arg(gw),
    )


def _model_evaluator(camera, R, t_lines_s, acceleration_mps2, n_nodes):
    """``averaged_model(camera, th, R, t_lines_s, acceleration_mps2, n_nodes)`` as a function of ``th`` (P, 6).

    The fit evaluates the model at the same lines several times per ball:
    with ``n_nodes <= 3`` (one kernel call on every line) the fixed
    arguments are converted once.
    """
    if n_nodes > 3:
        return lambda th: averaged_model(camera, th, R, t_lines_s, acceleration_mps2, n_nodes)
    t = as_arg(np.asarray(t_lines_s, dtype=float).reshape(1, -1))
    args = _kernel_args(camera, R, acceleration_mps2, n_nodes)

    def evaluate(th):
        left, right, presence, area, spread, valid, _, _, _ = averaged_samples(as_arg(th), t, *args, True, False)
        return ModelEdges(left, right, presence, area, spread, valid)

    return evaluate


def param_scale(camera: LineScanCamera, motion: BallMotion) -> np.ndarray:
    """Natural sizes of ``(t_c, y0, z0, vx, vy, vz)``: one line period, one
    pixel's footprint at the ball (metres), and 0.1 % of the speed (m/s)."""
    z = max(abs(motion.position_m[2]), 1e-3)
    v = max(motion.speed_mps, 1e-6)
    px_m = z / camera.focal_px
    return np.array([1.0 / camera.line_rate_hz, px_m, px_m, 1e-3 * v, 1e-3 * v, 1e-3 * v])


def model_jacobian(
    camera: LineScanCamera,
    theta: np.ndarray,
    radius_m: float,
    t_lines_s: np.ndarray,
    scale: np.ndarray,
    acceleration_mps2=(0.0, 0.0, 0.0),
    rel_step: float = 1e-3,
    n_nodes: int = 4,
) -> tuple[ModelEdges, np.ndarray, np.ndarray, np.ndarray]:
    """Model and its Jacobian (left, right, area with respect to theta).

    Forward differences with steps ``rel_step * scale`` evaluated in one
    vectorised call.  Returns ``(model, d_left, d_right, d_area)`` with the
    derivatives of shape (N, 6), in pixels per parameter unit.
    """
    theta = np.asarray(theta, dtype=float)
    h = rel_step * np.asarray(scale, dtype=float)
    thetas = np.vstack([theta, theta + np.diag(h)])
    me = averaged_model(camera, thetas, radius_m, t_lines_s, acceleration_mps2, n_nodes)
    dl = ((me.left_px[1:] - me.left_px[0]) / h[:, None]).T
    dr = ((me.right_px[1:] - me.right_px[0]) / h[:, None]).T
    da = ((me.area_px[1:] - me.area_px[0]) / h[:, None]).T
    base = ModelEdges(
        me.left_px[0], me.right_px[0], me.presence[0], me.area_px[0], me.spread_px[0], me.valid[0], None
    )
    return base, dl, dr, da


def chord_jacobian(
    camera: LineScanCamera,
    theta: np.ndarray,
    radius_m: float,
    t_lines_s: np.ndarray,
    acceleration_mps2=(0.0, 0.0, 0.0),
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Chord-model edges and their analytic derivatives with respect to theta.

    The chord model (:func:`ballscan.model.silhouette.silhouette`, ``model="chord"``)
    cuts the sphere by the plane ``x = 0`` at the line's centre time.  With
    ``tau = t - t_c``, the centre ``x = vx tau``, ``y = y0 + vy tau``,
    ``w = z0 + vz tau`` (plus ``a tau^2 / 2`` for a known acceleration) and
    ``rho^2 = R^2 - x^2``, the tangents are

        n_pm = (y w +- rho s) / D,   D = w^2 - rho^2,   s = sqrt(y^2 + D),

    and ``u = c + f distort(n)``.  The derivatives are taken in closed form
    (chain rule through ``x, y, w``; ``d rho / d x = -x / rho``,
    ``d s / d x = x / s``).

    Parameters
    ----------
    camera : LineScanCamera
    theta : ndarray (6,)
        ``(t_c, y0, z0, vx, vy, vz)`` in s, m, m, m/s, m/s, m/s.
    radius_m : float
        Ball radius, m.
    t_lines_s : ndarray (N,)
        Line centre times, s.
    acceleration_mps2 : sequence of 3 floats
        Known acceleration (camera frame), m/s^2.

    Returns
    -------
    left_px, right_px : ndarray (N,)
        Chord edges, pixels; NaN where the plane misses the ball or a
        tangent would point backwards.
    d_left, d_right : ndarray (N, 6)
        Their derivatives, pixels per parameter unit (NaN where the edges are).
    """
    u, J, ok, _, _, _ = _chord_core(camera, theta, radius_m, np.asarray(t_lines_s, dtype=float).reshape(-1), acceleration_mps2)
    if not ok.all():
        u = np.where(ok, u, np.nan)
        J = np.where(ok[:, None], J, np.nan)
    return u[0], u[1], J[0], J[1]


def _chord_core(camera, theta, radius_m, t, acceleration_mps2):
    """:func:`chord_jacobian`'s work: ``(u (2, N), J (2, N, 6), ok (N,), x, w, tau)``.

    ``u`` and ``J`` hold the left (row 0) and right (row 1) edges and their
    derivatives, finite garbage where ``ok`` is False; ``x, w`` are the
    centre's offset from the viewing plane and its depth at each line, m,
    ``tau = t - t_c``, s.  One compiled loop over the lines
    (:func:`ballscan.model._forward_kernels.chord_edges`).
    """
    return chord_edges(
        as_arg(theta), as_arg(t), float(radius_m),
        float(camera.focal_px), float(camera.principal_px), float(camera.k1), float(camera.k2),
        np.array([float(a) for a in acceleration_mps2]),
    )


def _fd_rows(camera, theta, R, t, fd, inside, h, dl, dr, acc, n_nodes, base=None):
    """Forward differences of the averaged model on the lines ``fd``, (n_fd, 6) each.

    On lines ``inside`` (the section offsets stay inside the ball: presence
    1) the averaged edge is the chord edge plus a correction that depends on
    the offset ``x0 = vx (t - t_c)`` (and the exposure's ``A``, which scales
    with ``vx``) and, to 1e-5 of the derivatives, on nothing else: only the
    ``t_c`` and ``vx`` columns are differenced there, the others are the
    chord's (``dl``, ``dr``).  The other lines get all six columns.  All
    parameter sets and lines go through one model call (times per set).
    ``base = (left, right, area)`` (all lines, the model at ``theta`` with
    ``n_nodes``) spares the base set's evaluation.
    """
    idx = np.flatnonzero(fd)
    ins = inside[idx]
    i_in, i_out = idx[ins], idx[~ins]
    n_in, n_out = i_in.size, i_out.size
    # parameter sets (None: the base set) on the inside lines and on the others
    cols_in = [0, 3] if base is not None else [None, 0, 3]
    cols_out = list(range(6)) if base is not None else [None, 0, 1, 2, 3, 4, 5]
    groups = ((cols_in, i_in), (cols_out, i_out))
    M = len(cols_in) * n_in + len(cols_out) * n_out
    th_all = np.empty((M, 6))
    th_all[:] = theta
    t_all = np.empty(M)
    o = 0
    for cols, ii in groups:
        for col in cols:
            sl = slice(o, o + ii.size)
            t_all[sl] = t[ii]
            if col is not None:
                th_all[sl, col] += h[col]
            o += ii.size
    me = _edges_model(camera, th_all, R, t_all[:, None], acc, n_nodes)
    L, Rr, A = me.left_px[:, 0], me.right_px[:, 0], me.area_px[:, 0]
    out = []
    o = 0
    for cols, ii in groups:
        k = len(cols)
        vals = [v[o : o + k * ii.size].reshape(k, ii.size) for v in (L, Rr, A)]
        o += k * ii.size
        if base is not None:
            # base values from the caller's evaluation at theta (same model and nodes)
            vals = [np.vstack([b[ii][None, :], v]) for b, v in zip(base, vals)]
        out.append(vals)
    fl = np.empty((idx.size, 6))
    fr = np.empty((idx.size, 6))
    fa = np.empty((idx.size, 6))
    if n_in:
        l3, r3, _ = out[0]
        gl, gr = dl[i_in], dr[i_in]  # copies (fancy indexing)
        hc = h[[0, 3]][:, None]
        gl[:, [0, 3]] = ((l3[1:] - l3[0]) / hc).T
        gr[:, [0, 3]] = ((r3[1:] - r3[0]) / hc).T
        fl[ins], fr[ins], fa[ins] = gl, gr, gr - gl
    if n_out:
        l7, r7, a7 = out[1]
        fl[~ins] = ((l7[1:] - l7[0]) / h[:, None]).T
        fr[~ins] = ((r7[1:] - r7[0]) / h[:, None]).T
        fa[~ins] = ((a7[1:] - a7[0]) / h[:, None]).T
    return fl, fr, fa


def hybrid_jacobian(
    camera: LineScanCamera,
    theta: np.ndarray,
    radius_m: float,
    t_lines_s: np.ndarray,
    scale: np.ndarray,
    acceleration_mps2=(0.0, 0.0, 0.0),
    fd_lines: np.ndarray | None = None,
    needed: np.ndarray | None = None,
    reach_limit: float = 0.8,
    rel_step: float = 1e-3,
    n_nodes: int = 3,
    memo: dict | None = None,
    reuse_px: float = 0.1,
    base: tuple[np.ndarray, np.ndarray, np.ndarray] | None = None,
    analytic: bool = False,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Jacobian of the averaged model: analytic chord derivatives inside, finite differences at the ends.

    On a line whose section offsets stay well inside the ball (``|x0| +
    A + B <= reach_limit * R``, with ``A`` the exposure's and ``B`` the pixel
    height's half-width of the offset, see :func:`ballscan.model.silhouette.silhouette`)
    the averaged edge is the chord edge plus a small, smooth correction
    (about half the edge's second derivative in the offset times the
    offset's variance: 0.002-0.005 px there); its derivative is that of the
    chord (:func:`chord_jacobian`) to 0.1 % of the largest term.  The other
    lines (the ball's ends, where the correction grows, and ``fd_lines``)
    get the forward differences of :func:`model_jacobian` with the averaged
    model, in one vectorised call over those lines only: on the lines whose
    section offsets stay inside the ball only the ``t_c`` and ``vx`` columns
    (the correction depends on the parameters through ``x0 = vx (t - t_c)``;
    the other columns' part is below 1e-5 of the derivatives), all six on
    the others (:func:`_fd_rows`).

    Parameters
    ----------
    camera, theta, radius_m, t_lines_s, scale, acceleration_mps2, rel_step, n_nodes
        As for :func:`model_jacobian`.
    fd_lines : ndarray of bool (N,), optional
        Lines that always get finite differences (e.g. area residuals).
    needed : ndarray of bool (N,), optional
        Lines whose derivatives are used; the others are left at the chord
        derivative (or NaN) without finite differences.
    reach_limit : float
        See above; 0 gives finite differences everywhere.
    memo : dict, optional
        Filled with the finite differences and their difference from the
        chord derivatives; a later call that needs no new line and whose
        ``theta`` moved the model's edges on those lines by at most
        ``reuse_px`` (to first order) reuses them: the chord derivatives at
        ``theta`` plus the stored correction (the whole stored row where the
        chord has no edge).  The correction is 0.5 % of the derivative at
        most and changes by a small fraction of that over such a move.
        ``memo["last_fd"]`` is set to the lines of this call's finite
        differences.
    reuse_px : float
        See ``memo`` (pixels).
    base : tuple of ndarray (N,), optional
        ``(left, right, area)`` of the averaged model at ``theta`` with
        ``n_nodes`` nodes on every line, when the caller has them: the
        finite differences then evaluate only the perturbed sets.
    analytic : bool
        On the lines that would get finite differences, the averaged
        model's exact derivatives instead
        (:func:`ballscan.model._forward_kernels.averaged_edges_jacobian`; without a known
        acceleration; one compiled call with the chord's,
        :func:`ballscan.solve._fit_kernels.hybrid_rows`); ``memo`` is then only told
        the lines.

    Returns
    -------
    d_left, d_right, d_area : ndarray (N, 6)
        Derivatives of the averaged model's left and right edges and area,
        pixels per parameter unit.
    """
    theta = np.asarray(theta, dtype=float)
    t = np.asarray(t_lines_s, dtype=float).reshape(-1)
    R = float(radius_m)
    if analytic and not any(acceleration_mps2):
        # the chord's derivatives, the lines that need the averaged model's
        # exact ones and those, in one compiled call
        g, gw = _gauss(n_nodes)
        no_lines = np.zeros(0, dtype=bool)
        dl, dr, da, fd = hybrid_rows(
            as_arg(theta), as_arg(t), R, float(camera.exposure), float(camera.focal_px), float(camera.principal_px),
            float(camera.k1), float(camera.k2), as_arg(g), as_arg(gw), reach_limit * R,
            no_lines if fd_lines is None else as_arg(fd_lines, np.bool_),
            no_lines if needed is None else as_arg(needed, np.bool_),
            fd_lines is not None, needed is not None,
        )
        if memo is not None:
            memo["last_fd"] = fd
        return dl, dr, da
    u, J, chord_ok, x0, z, tau = _chord_core(camera, theta, R, t, acceleration_mps2)
    dl, dr = J[0], J[1]
    ax = float(acceleration_mps2[0])
    vxt = np.abs(theta[3] + ax * tau) if ax else abs(float(theta[3]))
    reach = np.abs(x0) + vxt * (camera.exposure / 2.0) + np.maximum(z, 0.0) / (2.0 * camera.focal_px)
    fd = ~chord_ok | (reach > reach_limit * R)
    if fd_lines is not None:
        fd |= fd_lines
    if needed is not None:
        fd &= needed
    da = dr - dl
    if memo is not None:
        memo["last_fd"] = fd
    if not fd.any():
        return dl, dr, da
    scale = np.asarray(scale, dtype=float)
    if memo is not None and memo.get("theta") is not None and memo["n"] == t.size and memo["have"][fd].all():
        # how far the model moved on those lines since (pixels, first order)
        step = theta - memo["theta"]
        if np.abs(memo["fd_l"][fd] @ step).max() <= reuse_px and np.abs(memo["fd_r"][fd] @ step).max() <= reuse_px:
            # finite differences taken nearby: keep their difference to the
            # chord derivatives (a small, slowly varying correction), or the
            # whole row where the chord has none (lines at or past the ends)
            keep_row = fd & chord_ok & memo["chord_ok"]
            whole = fd & ~keep_row
            for cur, corr, old in ((dl, memo["corr_l"], memo["fd_l"]), (dr, memo["corr_r"], memo["fd_r"]), (da, memo["corr_a"], memo["fd_a"])):
                cur[keep_row] += corr[keep_row]
                cur[whole] = old[whole]
            return dl, dr, da
    h = rel_step * scale
    fl, fr, fa = _fd_rows(camera, theta, R, t, fd, chord_ok & (reach < R), h, dl, dr, acceleration_mps2, n_nodes, base)
    if memo is not None:
        if memo.get("n") != t.size:
            for k in ("fd_l", "fd_r", "fd_a", "corr_l", "corr_r", "corr_a"):
                memo[k] = np.zeros((t.size, 6))
        memo["fd_l"][fd], memo["fd_r"][fd], memo["fd_a"][fd] = fl, fr, fa
        memo["corr_l"][fd], memo["corr_r"][fd], memo["corr_a"][fd] = fl - dl[fd], fr - dr[fd], fa - da[fd]
        memo.update(theta=theta.copy(), n=t.size, have=fd.copy(), chord_ok=chord_ok)
    dl[fd], dr[fd], da[fd] = fl, fr, fa
    return dl, dr, da


# ------------------------------------------------------------------- results


@dataclass(frozen=True)
class FitSettings:
    """Choices of :func:`fit_motion`.

    Attributes
    ----------
    fit_edge_bias : bool
        Fit the symmetric edge bias ``b`` (pixels) as a nuisance parameter.
    max_spread_px : float
        Edges are used only where the model's edge spread over the exposure
        and pixel height is below this (pixels); wider transitions escape the
        local area window and those lines contribute their area instead.
    max_spread_wide_px : float
        Lines whose model edge spread lies between ``max_spread_px`` and this
        (pixels) use the wide-window edges
        (:attr:`ballscan.measure.edges.EdgeMeasurements.left_wide_px`) instead.
    edge_floor_px : float
        Systematic 1-sigma added in quadrature to each edge sigma, pixels
        (limb shading and felt texture that the local level cannot follow).
        On the clean reference scenes the measured edges differ from the
        renderer's exact coverage edges by 0.049 px RMS on uniform limbs
        (texture indicator < 0.01 px) and 0.08-0.14 px next to seams; the
        part above the floor is carried by ``texture_gain``, by the reduced
        chi-square scaling and by ``correlation_inflation`` (which see the
        actual scatter), so that a plain noisy ball keeps its pixel-noise
        sigma.  0.015 px since the shading-aware second pass
        (:mod:`ballscan.measure.shading`): with 0.02 the speed's 1-sigma covered
        78.5 % of 200 noisy flat renders at 30 degrees (too wide), with
        0.015 75.5 %.
    matched_floor_px : float
        The same for the edges that :func:`ballscan.measure.edges.matched_edges`
        measured (``left_matched`` / ``right_matched`` of the edges): the
        model's own error on them, RMS 0.0007 px and at most 0.0025 px on a
        noise-free, finely sampled render of the benchmark ball.
    texture_gain : float
        Multiplies the edges' texture indicator
        (:attr:`ballscan.measure.edges.EdgeMeasurements.left_texture_px`), added in
        quadrature to each edge sigma: edges next to a seam or a steep
        shading gradient get a larger sigma.
    end_line_areas : bool
        Fit the summed coverage of lines with signal but no usable edge pair
        (the ball's ends).  Without a brightness level for the line (edges
        measured without a shading model) the sum is weighted by the
        unknown brightness of the ball's cap, which a shaded ball's lighting
        changes between its leading and trailing ends by tens of per cent,
        hence the large ``area_rel_sigma``; with one see
        ``area_level_floor``.  Lines without signal (the ball is absent)
        always give area residuals.
    pixels : bool
        Fit the pixels of the ball's ends instead of their edges and areas
        (:func:`_pixel_residuals`): on every line whose model edge spread is
        at least ``pixel_min_spread_px`` (seen during the whole exposure, or
        also partly with ``pixel_partial``) the pixels within ``spread / 2 + pixel_window_px`` of each model
        edge, and every pixel of the end lines without an edge pair, each
        modelled as a free brightness times the shading model's relative
        surface brightness (``profile_shade`` of the edges) times the
        pixel's coverage averaged over the exposure and its height.  The
        edges of a spread end keep only their mean over the exposure; the
        pixels keep how the edge moved during it, which is where a
        line-scan image holds most of its information on ``t_c``, ``vx``
        and ``vz``.  For uniform (untextured) balls and a continuous
        exposure (real cameras): with the defaults below the flat benchmark
        ball's V.z RMSE is 1.08-1.09x its pixel Cramér–Rao bound, its speed
        RMSE 1.10x (30 deg) and 1.62x (0 deg, second order in V.z) against
        1.9-2.6x with edges and areas, but on the reference scenes (textured
        balls, an exposure sampled at 4 instants) the median error grew from
        0.25 % to 2.5 %.  Off by default.
    pixel_min_spread_px : float
        Lines whose model edge spread is below this keep their edges.  0
        (every line's pixels): the edges of the sharp lines, with their level
        runs' noise, left ``z0`` 1.7-1.9x and ``vz`` 1.25-1.55x their bounds
        with 0.3 px here, against 0.9-1.1x and 1.0-1.15x (60 noise draws,
        flat benchmark ball at 0 and 30 deg).
    pixel_window_px : float
        Half-width of the pixel windows beyond half the edge spread, pixels
        (the windows must reach the ball's level on both sides of the edge:
        that level is the brightness of the model).  3 and 6 gave the same
        accuracy on the benchmark ball (60 noise draws), 3 at less cost.
    pixel_nodes : int
        Gauss-Legendre nodes per piece of the exposure in the pixel model
        (3 leaves the spread edges' ramps a staircase: a 0.15 m/s speed bias
        on the 30-degree benchmark).  8 still does, on long balls: the
        default fit's spread-pixel pass takes 32 (``estimate._SPREAD_PIXELS``:
        V.x moved 0.3-0.5 sigma from 8 to 32 on the quick Fig. 5 sweep's
        long balls, 0.07-0.10 from 32 to 64); the opt-in pixel fit keeps 8.
    pixel_jacobian : {"analytic", "fd"}
        The pixel residuals' Jacobian: exact, by forward-mode derivatives in
        one compiled pass (:func:`ballscan.model._forward_kernels.pixel_residuals_jacobian`;
        without a known acceleration), or forward differences of six
        perturbed evaluations (``"fd"``, and always with an acceleration).
        On the 30-degree benchmark ball the differences (step 1e-3 of the
        parameter scale) were 4 % off in the ``t_c`` column; the exact one
        moved the solutions by at most 0.04 sigma, and the fit took 0.84x
        the time.
    pixel_groups : {"end", "window"}
        One free brightness per end of the ball (before / after ``t_c``;
        uniform balls) or per edge window (the local level, as the edges
        have it: robust to texture, but the level's noise then spoils most
        of the information).
    pixel_partial : bool
        Also fit the pixels of the lines seen during only part of the
        exposure (their areas depend on how the exposure is sampled).
    pixel_floor : float
        Systematic 1-sigma of a fitted pixel's normalised value, added in
        quadrature.
    level_areas : bool
        Divide the end lines' areas by the ball's local brightness next to
        them (:func:`_area_levelled`).
    level_lines : int
        Nearest lines with a measured inner level used for it.
    reject_sigma : float
        After each fit, edges whose whitened residual exceeds this many
        robust standard deviations (``max(1, 1.4826 MAD)``) are rejected and
        the fit is repeated (texture outliers; never the area residuals).
    max_reject_rounds : int
        Rounds of rejection and refitting at most.
    correlation_inflation : bool
        Multiply the covariance by ``(1 + rho) / (1 - rho)`` (at most 10),
        ``rho`` the larger lag-one autocorrelation of the whitened edge
        residuals along each side, less ``2 / sqrt(n)`` (what white noise
        reaches by chance), and scale it at least by the variance ratio of
        block means of the residuals (:func:`_block_scale`): shading and
        seam biases are correlated over many lines and a fit that treats
        them as independent would report too small a sigma.
    area_rel_sigma : float
        Relative systematic 1-sigma of an end line's area (its brightness is
        the lit or shaded cap's, not the ball's mean brightness), added in
        quadrature.  The default 3 leaves the end lines little say on size
        and timing (with 0.15 they biased ``vz`` by 4 sigma on noisy shaded
        renders) but keeps them as a weak anchor of where the ball is seen.
    area_floor_px : float
        Added in quadrature to each area sigma, pixels.
    area_level_floor : float
        Relative systematic 1-sigma of the brightness model's level of an
        end line (:attr:`ballscan.measure.edges.EdgeMeasurements.area_level`), added
        in quadrature to the level's texture sigma.  Where the edges carry
        such a level, the line's area divided by it is a covered length with
        the sigma of its pixel noise, this and the texture, in place of
        ``area_rel_sigma``: the ball's ends, where the chord grows like the
        square root of time, hold most of the information on ``t_c``,
        ``vx`` and ``vz`` that the edges of the spread ends cannot give.
    area_level_floor_px : float
        Added in quadrature to the sigma of a levelled area, pixels.
    area_level_partial : bool
        Also level the lines on which the ball is present during only part
        of the exposure (its first and last lines).  Their area depends on
        how the exposure is sampled: a renderer with a few discrete exposure
        sub-frames makes it differ from the continuous average.
    area_partial_check : float
        Without ``area_level_partial`` (and without ``pixels``): fit those
        lines levelled anyway and keep them so only if they pass
        :func:`_partial_verdict`: the ball has them at both ends, each one's
        levelled area lies within this many sigma of the loose fit's model
        (one Gauss-Newton step away) and the move between the two fits
        passes a Hausman test at ``partial_shift_p``; otherwise the fit is
        solved again with them loose.  A continuous exposure (a real camera,
        a finely sampled render) passes; a ball cut by the image's first or
        last line does not.  0: never level them.
    partial_shift_p : float
        False-alarm rate of that Hausman test.  On the POV-Ray reference
        scenes (4 exposure sub-frames) the lines pass one by one on most
        balls, and the test is what sends the close pair's first ball back
        to the loose fit.
    loss, f_scale : str, float
        Robust loss of :func:`scipy.optimize.least_squares` and its scale in
        sigmas.
    min_edge_lines : int
        Fewer lines with both edges usable make the fit degenerate.
    n_nodes : int
        Quadrature nodes per piece of the averaged model.
    max_nfev : int
        Model evaluations allowed.
    cost_tol : float
        The built-in solver stops when the next step would lower half the
        chi-square by less than this (1e-5: a remaining move of about
        0.003 sigma; smaller values mostly add steps that only trade the
        Jacobian's last digits).
    stall_tol : float
        A step that does not lower the cost but raises it by at most this,
        where both it and the undamped Gauss-Newton step would lower half
        the chi-square by less than this (1e-3: a move of about 0.03 sigma),
        also ends the solve (converged).
    jacobian_refresh : float
        After an accepted step that lowered half the chi-square by more than
        this (predicted), the Jacobian is recomputed; after smaller steps the
        previous one is kept (chord steps near the minimum, where the model
        is linear over the remaining move).  0.1: with the mostly analytic
        Jacobian a refresh costs about two model evaluations and saves the
        slow chord steps that a stale one takes.
    jacobian_nodes : int
        Quadrature nodes per piece of the model inside the finite-difference
        Jacobian (the residuals use ``n_nodes``); the Jacobian only steers
        the steps and the covariance (2 nodes err by 0.1 px at the ends,
        3 nodes by 1e-4 px).
    broyden : bool
        Update the Jacobian by Broyden's rank-one formula between exact
        (finite-difference) Jacobians (see :func:`_levenberg_marquardt`).
        Off by default: on the serve it took more steps (15 against 9 model
        evaluations) and stopped 0.005 m/s off in ``vz`` on noise-free edges.
    edge_jacobian : {"analytic", "fd"}
        The Jacobian rows of the lines where the chord's derivative does not
        hold (the ball's ends, the area lines; see ``jacobian_reach``):
        exact, by forward-mode derivatives of the averaged model in one
        compiled pass (:func:`ballscan.model._forward_kernels.averaged_edges_jacobian`;
        without a known acceleration), or its forward differences
        (``"fd"``, with ``jacobian_nodes`` and the reuse of ``jacobian_reuse_px``).
    jacobian_reach : float
        Lines whose section offsets stay within this fraction of the radius
        get the analytic derivatives of the chord model in the Jacobian
        (:func:`hybrid_jacobian`; 0.1 % of the finite-difference Jacobian's
        largest term at 0.8); the ball's ends and the area lines get finite
        differences of the averaged model.  0 uses finite differences on
        every line (:func:`model_jacobian`).
    jacobian_reuse_px : float
        The finite-difference rows are recomputed only after the model's
        edges on those lines moved by more than this (pixels) since they
        were taken; nearer, their difference from the analytic chord
        derivatives is kept (``memo`` of :func:`hybrid_jacobian`).  0
        recomputes them every time.
    robust_first : bool
        Start with a fit under the robust ``loss`` before the least-squares
        rounds with outlier rejection (slower; the rejection rounds alone
        handle the texture outliers of the reference scenes).
    solver : {"gn", "scipy"}
        ``"gn"``: the built-in Levenberg-Marquardt (fast, see
        :func:`_levenberg_marquardt`); ``"scipy"``:
        :func:`scipy.optimize.least_squares` (``trf``, tight tolerances), kept
        as a cross-check.
    """

    fit_edge_bias: bool = False
    max_spread_px: float = 0.3
    max_spread_wide_px: float = 0.8
    end_line_areas: bool = True
    pixel_floor: float = 0.002
    pixels: bool = False
    pixel_min_spread_px: float = 0.0
    pixel_window_px: float = 3.0
    pixel_nodes: int = 8
    pixel_jacobian: str = "analytic"
    pixel_groups: str = "end"
    pixel_partial: bool = True
    level_areas: bool = False
    edge_floor_px: float = 0.015
    matched_floor_px: float = 0.003
    texture_gain: float = 1.0
    level_lines: int = 3
    reject_sigma: float = 3.5
    max_reject_rounds: int = 3
    correlation_inflation: bool = True
    area_rel_sigma: float = 3.0
    area_floor_px: float = 0.1
    area_level_floor: float = 0.002
    area_level_floor_px: float = 0.005
    area_level_partial: bool = False
    area_partial_check: float = 4.0
    partial_shift_p: float = 0.01
    loss: str = "soft_l1"
    f_scale: float = 3.0
    min_edge_lines: int = 5
    n_nodes: int = 3
    max_nfev: int = 60
    solver: str = "gn"
    cost_tol: float = 1e-5
    stall_tol: float = 1e-3
    jacobian_refresh: float = 0.1
    jacobian_nodes: int = 3
    broyden: bool = False
    robust_first: bool = False
    jacobian_reach: float = 0.8
    edge_jacobian: str = "analytic"
    jacobian_reuse_px: float = 0.1


@dataclass(frozen=True)
class FitResult:
    """Outcome of :func:`fit_motion`.

    Attributes
    ----------
    motion : BallMotion
        The fitted motion (camera frame; ``V.x >= 0`` unless the camera
        states the crossing direction).
    covariance : ndarray (6, 6)
        Covariance of ``(t_c, y0, z0, vx, vy, vz)`` (s, m, m/s), scaled by
        ``max(1, chi2_red)`` (module docstring); NaN rows/columns for
        undetermined parameters.
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

    @property
    def sigmas(self) -> np.ndarray:
        """1-sigma of the six parameters (s, m, m, m/s, m/s, m/s)."""
        return np.sqrt(np.diag(self.covariance))

    @property
    def degenerate(self) -> bool:
        return bool(self.undetermined)


# ------------------------------------------------------------------- the fit


def _select(edges: EdgeMeasurements, me: ModelEdges, settings: FitSettings):
    """Which lines give edge residuals (narrow or wide window) and which give area residuals.

    Edges where the model sees the ball during the whole exposure, with its
    edge spread at most ``max_spread_px`` (the narrow window's edges) or up
    to ``max_spread_wide_px`` (the wide window's); area lines: no usable
    edge, and the line's area is not spoiled (``edges.end_line``), or no
    signal at all (lines around the ball).  Returns ``(use_l, use_r, use_a,
    wide_l, wide_r)``; one compiled pass (:func:`ballscan.solve._fit_kernels.select_lines`).
    """
    wide = edges.left_wide_px is not None and settings.max_spread_wide_px > settings.max_spread_px
    e = edges
    masks = [as_arg(m, np.bool_) for m in (me.valid, e.left_ok, e.right_ok, e.end_line)]
    # (the narrow window's arrays stand in for the wide one's, unread, when it is not used)
    if wide:
        wl_ok, wr_ok, wl, wr = e.left_wide_ok, e.right_wide_ok, e.left_wide_px, e.right_wide_px
    else:
        wl_ok, wr_ok, wl, wr = e.left_ok, e.right_ok, e.left_px, e.right_px
    return select_lines(
        as_arg(me.presence), masks[0], as_arg(me.spread_px), masks[1], masks[2], as_arg(e.left_px), as_arg(e.right_px), masks[3],
        wide, as_arg(wl_ok, np.bool_), as_arg(wr_ok, np.bool_), as_arg(wl), as_arg(wr),
        float(settings.max_spread_px), float(settings.max_spread_wide_px), bool(settings.end_line_areas),
    )


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


def _levenberg_marquardt(resid_only, resid_and_jac, x0: np.ndarray, settings: "FitSettings", start=None, loss: str | None = None):
    """Levenberg-Marquardt with iteratively reweighted robust loss.

    Steps are solved on the column-equilibrated normal equations (the
    parameters' sizes differ by ~1e8).  It stops when the Gauss-Newton step
    would lower the cost by less than ``settings.cost_tol`` (in units of
    half the chi-square: 1e-5 is a move of about 0.003 sigma), which, unlike a
    relative ``ftol``, does not stop early along the weak ``vz`` direction.
    The Jacobian (``resid_and_jac``) is computed at the start (or taken from
    ``start = (r, J)``; ``r`` None is recomputed) and after accepted steps
    that lowered the cost by more than ``settings.jacobian_refresh`` (other
    steps are chord steps with the previous one); with ``settings.broyden``
    it is instead corrected after every trial step by Broyden's rank-one
    update, so that a step costs one model evaluation.  ``loss`` (default
    ``settings.loss``) is the robust loss.  Returns ``(x, n_eval, status,
    message, cost, r, J)`` with the last Jacobian (taken at or next to
    ``x``).
    """
    f2 = settings.f_scale**2
    tol = settings.cost_tol
    loss = settings.loss if loss is None else loss

    linear = loss == "linear"

    def cost_of(r):
        if linear:
            return 0.5 * float(r @ r)
        return 0.5 * f2 * float(_rho((r * r) / f2, loss)[0].sum())

    x = np.asarray(x0, dtype=float).copy()
    if start is None:
        r, J = resid_and_jac(x)
        n_eval = 1
    else:
        r, J = start
        J = J.copy()
        n_eval = 0
        if r is None:
            r = resid_only(x)
            n_eval = 1
    cost = cost_of(r)
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
                r, J = resid_and_jac(x)
                n_eval += 1
                n_fresh = 1
                continue
            return x, n_eval, 1, f"converged: predicted cost decrease below {tol:g}", cost, r, J
        dx = step / cn
        x_new = x + dx
        r_new = resid_only(x_new)
        n_eval += 1
        ok = bool(np.all(np.isfinite(r_new)))
        if broyden and ok:
            J = J + np.outer(r_new - r - J @ dx, dx) / float(dx @ dx)
        cost_new = cost_of(r_new) if ok else math.inf
        if cost_new <= cost:
            lam = max(lam / 10.0, 1e-9)
            x, cost, r = x_new, cost_new, r_new
            n_fresh = 0
            if not broyden and predicted > settings.jacobian_refresh:
                # far from the minimum: the model's curvature matters, take
                # a fresh Jacobian; close to it the old one is kept (a chord
                # step costs one evaluation and moves well below a sigma)
                r, J = resid_and_jac(x)
                n_eval += 1
        else:
            if predicted < settings.stall_tol and cost_new - cost <= settings.stall_tol and _gn_decrease(A, g) < settings.stall_tol:
                # the last hundredths of a sigma (the undamped step's too, so
                # that heavy damping cannot fake it): the averaged model's
                # quadrature is not smooth at this scale, and damping the
                # step further only spends evaluations (up to 7 at 30 deg)
                return x, n_eval, 1, f"converged: no step lowers the cost, predicted decrease below {settings.stall_tol:g}", cost, r, J
            lam *= 10.0
            if lam > 1e10:
                return x, n_eval, 0, "stopped: no step lowers the cost", cost, r, J
    return x, n_eval, 0, f"stopped: {settings.max_nfev} evaluations", cost, r, J


def _gn_decrease(A: np.ndarray, g: np.ndarray) -> float:
    """First-order decrease of half the chi-square along the undamped Gauss-Newton step (normal matrix ``A``, gradient ``g``)."""
    try:
        step = np.linalg.solve(A, g)
    except np.linalg.LinAlgError:
        step = np.linalg.lstsq(A, g, rcond=None)[0]
    return float(g @ step)


def _weights(edges: EdgeMeasurements, me: ModelEdges, settings: FitSettings):
    """Residual selection and 1-sigma of every residual (pixels)."""
    use_l, use_r, use_a, wide_l, wide_r = _select(edges, me, settings)
    return _weights_masked(edges, use_l, use_r, use_a, settings, wide_l, wide_r)


def whitened_jacobian(
    camera: LineScanCamera, edges: EdgeMeasurements, motion: BallMotion, settings: FitSettings = FitSettings()
) -> tuple[np.ndarray, tuple[str, ...]]:
    """Jacobian of the fit's whitened residuals at ``motion``.

    Same edge and area selection and weights as :func:`fit_motion` with
    ``area_level_partial`` and without ``pixels`` (the pixel residuals are
    not included; :func:`ballscan.solve.precision.pixel_crlb` bounds those); one column per
    parameter of :data:`PARAM_NAMES` plus ``edge_bias_px`` when
    ``settings.fit_edge_bias``.  ``J^T J`` is the Fisher information of the
    edge measurements (Gaussian noise), used by :mod:`ballscan.solve.precision`.
    """
    theta = motion.to_params()
    scale = param_scale(camera, motion)
    me, dl, dr, da = model_jacobian(camera, theta, motion.radius_m, edges.t_s, scale, motion.acceleration_mps2, n_nodes=settings.n_nodes)
    use_l, use_r, use_a, sl, sr, sa, _, _, _ = _weights(edges, me, settings)
    J = np.vstack([dl[use_l] / sl[:, None], dr[use_r] / sr[:, None], da[use_a] / sa[:, None]])
    names = PARAM_NAMES
    if settings.fit_edge_bias:
        jb = np.concatenate([-1.0 / sl, 1.0 / sr, np.zeros(int(use_a.sum()))])
        J = np.hstack([J, jb[:, None]])
        names = names + (_DILATION,)
    return J, names


def fit_motion(
    camera: LineScanCamera,
    edges: EdgeMeasurements,
    initial: BallMotion,
    settings: FitSettings = FitSettings(),
) -> FitResult:
    """Fit the averaged-silhouette model to one ball's edge measurements.

    Parameters
    ----------
    camera : LineScanCamera
    edges : EdgeMeasurements
        From :func:`ballscan.measure.edges.measure_edges` (or :func:`synthetic_edges`).
    initial : BallMotion
        Starting point (e.g. the paper's key-point guess); its radius and
        known acceleration are kept fixed.
    settings : FitSettings

    Returns
    -------
    FitResult
        Never raises for a degenerate geometry: ``undetermined`` names the
        parameters the image cannot determine and ``converged`` is False when
        the optimiser did not converge.
    """
    t0 = time.perf_counter()
    if settings.pixels and settings.pixel_groups not in ("end", "window"):
        raise ValueError(f"settings.pixel_groups: expected 'end' or 'window', got {settings.pixel_groups!r}")
    R = initial.radius_m
    acc = initial.acceleration_mps2
    nn = settings.n_nodes
    t = edges.t_s
    theta0 = initial.to_params()
    scale = param_scale(camera, initial)
    n_lines = t.size
    settings_rel_step = 1e-3  # model_jacobian's default step (fraction of `scale`)
    rejected_l = np.zeros(n_lines, dtype=bool)
    rejected_r = np.zeros(n_lines, dtype=bool)

    # the last model evaluation (one parameter set, all lines), shared by the
    # residual selection and the solver: a round's selection and its first
    # residuals are taken at the same point
    model_cache: dict = {}
    evaluate = _model_evaluator(camera, R, t, acc, nn)
    tables = _weight_tables(edges, settings)
    fd_memo: dict = {}  # finite-difference rows of the Jacobian (hybrid_jacobian's memo)
    jac_cache: dict = {}  # per-line derivatives of the last Jacobian, for the next round's start
    # the partial lines levelled (area_partial_check: first, then tested)
    level_partial = [settings.area_partial_check > 0 and not settings.area_level_partial and not settings.pixels]
    verdict = "off"

    def model_at(theta) -> ModelEdges:
        # always with the edge spread (a few more operations), so that the
        # next round's selection at the solution reuses the solver's last
        # evaluation
        key = np.asarray(theta, dtype=float)[:6].tobytes()
        me = model_cache.get("me")
        if me is None or model_cache["key"] != key:
            me = evaluate(np.asarray(theta, dtype=float)[None, :6])
            model_cache["key"], model_cache["me"] = key, me
        return me

    def problem(theta):
        """Residual selection and weights at ``theta``, less the rejected edges."""
        me = model_at(theta)
        me = ModelEdges(*(getattr(me, k)[0] for k in ("left_px", "right_px", "presence", "area_px", "spread_px", "valid")))
        ul, ur, ua, wl, wr = _select(edges, me, settings)
        ul, ur = ul & ~rejected_l, ur & ~rejected_r
        pix = None
        if settings.pixels and edges.profile is not None:
            # the ends seen during the whole exposure: their pixels instead of
            # their areas, and the spread edges' windows instead of the edges
            full = edges.signal & me.valid & ((me.presence >= 0.999) | settings.pixel_partial)
            end_p = ua & full
            spread_p = full & ~end_p & (me.spread_px >= settings.pixel_min_spread_px) & (ul | ur)
            pix = _pixel_spec(edges, me, end_p, spread_p, float(theta[0]), settings)
            if pix is not None:
                ua = ua & ~end_p
                ul, ur = ul & ~spread_p, ur & ~spread_p
        loose = None if (settings.area_level_partial or level_partial[0]) else me.presence < 0.999
        return _weights_masked(edges, ul, ur, ua, settings, wl, wr, tables, loose) + (pix,)

    def solve(x_start, sel, loss, start=None):
        use_l, use_r, use_a, sl, sr, sa, ml, mr, ma, pix = sel
        n_pix = 0 if pix is None else int(pix["n"])

        def pixel_res(thetas):
            if pix is None:
                return np.zeros((thetas.shape[0], 0))
            return _pixel_residuals(camera, thetas, R, pix, acc, nn)

        def pixel_jac(th, base_r):
            # the pixel residuals' Jacobian (M, 6) at th, whose residuals are base_r
            if pix is None:
                return np.zeros((0, 6))
            if settings.pixel_jacobian == "analytic" and not np.any(acc):
                return _pixel_residuals_jacobian(camera, th, R, pix, nn)
            h = settings_rel_step * scale
            return ((pixel_res(th + np.diag(h)) - base_r) / h[:, None]).T

        fit_b = len(x_start) == 7

        def unpack(x):
            return x[:6], (x[6] if fit_b else 0.0)

        used = use_l | use_r | use_a
        # the selected lines and their values in the compiled kernels' form
        il, ir, ia = np.flatnonzero(use_l), np.flatnonzero(use_r), np.flatnonzero(use_a)
        ml, mr, ma, sl, sr, sa = (as_arg(a) for a in (ml, mr, ma, sl, sr, sa))
        no_pixels = np.zeros(0)
        last: dict = {}

        def resid_and_jac(x):
            th, b = unpack(x)
            if settings.jacobian_reach > 0:
                key = x.tobytes()
                r = last["r"] if last.get("key") == key else resid_only(x)
                base = None
                if settings.jacobian_nodes == nn:
                    me0 = model_at(th)
                    base = (me0.left_px[0], me0.right_px[0], me0.area_px[0])
                dl, dr, da = hybrid_jacobian(
                    camera, th, R, t, scale, acc, fd_lines=use_a, needed=used,
                    reach_limit=settings.jacobian_reach, rel_step=settings_rel_step, n_nodes=settings.jacobian_nodes,
                    memo=fd_memo, reuse_px=settings.jacobian_reuse_px, base=base,
                    analytic=settings.edge_jacobian == "analytic",
                )
                # the base set's pixel residuals are the tail of r
                jp = pixel_jac(th, r[r.size - n_pix :])
            else:
                me, dl, dr, da = model_jacobian(camera, th, R, t, scale, acc, n_nodes=settings.jacobian_nodes)
                if settings.jacobian_nodes != nn:
                    me = averaged_model(camera, th[None], R, t, acc, nn)
                    me = ModelEdges(me.left_px[0], me.right_px[0], me.presence[0], me.area_px[0], me.spread_px[0], me.valid[0])
                pr0 = pixel_res(th[None])[0]
                jp = pixel_jac(th, pr0)
                r = np.concatenate(
                    [(me.left_px[use_l] - b - ml) / sl, (me.right_px[use_r] + b - mr) / sr, (me.area_px[use_a] - ma) / sa, pr0]
                )
            if pix is None:
                # lines whose area derivative is the averaged model's (finite differences)
                fd_rows = use_a | fd_memo["last_fd"] if settings.jacobian_reach > 0 else used
                jac_cache.update(dl=dl, dr=dr, da=da, used=used, fd_rows=fd_rows)
            else:
                jac_cache.clear()
            return r, assemble(dl, dr, da, jp)

        def assemble(dl, dr, da, jp):
            """Whitened Jacobian of this selection from per-line derivatives."""
            return fit_jacobian(as_arg(dl), as_arg(dr), as_arg(da), il, ir, ia, sl, sr, sa, as_arg(jp), fit_b)

        if start is None and pix is None and settings.solver == "gn" and jac_cache:
            # a later round (after rejecting edges) starts from the last
            # Jacobian's per-line derivatives, taken at or next to x_start,
            # when they cover this selection; its residuals are recomputed
            c = jac_cache
            if not np.any(used & ~c["used"]) and not np.any(use_a & ~c["fd_rows"]):
                start = (None, assemble(c["dl"], c["dr"], c["da"], np.zeros((0, 6))))

        def resid_only(x):
            th_, b_ = unpack(x)
            me = model_at(th_)
            tail = no_pixels if pix is None else as_arg(pixel_res(th_[None])[0])
            r = fit_residuals(me.left_px[0], me.right_px[0], me.area_px[0], il, ir, ia, float(b_), ml, mr, ma, sl, sr, sa, tail)
            last["key"], last["r"] = x.tobytes(), r
            return r

        if settings.solver == "scipy":
            cache: dict = {}

            def both(x):
                key = x.tobytes()
                if key not in cache:
                    cache.clear()
                    cache[key] = resid_and_jac(x)
                return cache[key]

            x_scale = np.concatenate([scale, [0.05]]) if fit_b else scale
            res = least_squares(
                lambda x: both(x)[0],
                x_start,
                jac=lambda x: both(x)[1],
                x_scale=x_scale,
                loss=loss,
                f_scale=settings.f_scale,
                method="trf",
                max_nfev=settings.max_nfev,
                xtol=1e-12,
                ftol=1e-12,
                gtol=1e-12,
            )
            r_end, J_end = resid_and_jac(res.x)
            out = (res.x, int(res.nfev), int(res.status), str(res.message), float(res.cost), r_end, J_end)
        elif settings.solver == "gn":
            out = _levenberg_marquardt(resid_only, resid_and_jac, x_start, settings, start=start, loss=loss)
        else:
            raise ValueError(f"settings.solver: expected 'gn' or 'scipy', got {settings.solver!r}")
        return out, resid_and_jac

    def edge_lines(sel) -> int:
        # lines with both edges, as edges or as the pixels of their windows
        pix = sel[-1]
        return int((sel[0] & sel[1]).sum()) + (0 if pix is None else pix["n_spread"])

    sel = problem(theta0)
    if level_partial[0]:
        if not _at_both_ends(_partial_lines(sel[2], model_at(theta0), tables), t, theta0[0]):
            # not at both ends (a ball cut by the image's first or last line): loose
            level_partial[0] = False
            verdict = "one_end"
            sel = problem(theta0)
    use_l, use_r, use_a = sel[:3]
    n_edge_lines = edge_lines(sel)
    fit_b = settings.fit_edge_bias and n_edge_lines >= settings.min_edge_lines
    n_par = 6 + int(fit_b)
    m_res = int(use_l.sum() + use_r.sum() + use_a.sum()) + (0 if sel[-1] is None else sel[-1]["n"])
    if n_edge_lines < settings.min_edge_lines or m_res <= n_par:
        return _degenerate_result(initial, n_edge_lines, settings, use_l, use_r, use_a, t0)
    x = np.concatenate([theta0, [0.0]]) if fit_b else theta0.copy()
    # (optionally a robust fit first, then) least squares at the current
    # selection, rejection of outlying edges, re-selection and refit until
    # nothing changes
    n_total = 0
    n_rejected = 0
    r = J = None
    rj = None
    sel_solved = None
    if settings.robust_first:
        (x, n_iter, status, message, cost, r, J), rj = solve(x, sel, settings.loss)
        sel_solved = sel
        n_total += n_iter
        sel = problem(x[:6])
    for _round in range(max(settings.max_reject_rounds, 0) + 1):
        if _round > 0:
            sel = problem(x[:6])
        use_l, use_r, use_a, sl, sr, sa = sel[:6]
        if edge_lines(sel) < settings.min_edge_lines:
            break
        (x, n_iter, status, message, cost, r, J), rj = solve(x, sel, "linear")
        sel_solved = sel
        n_total += n_iter
        if _round == settings.max_reject_rounds or settings.reject_sigma <= 0:
            break
        nl, nr = int(use_l.sum()), int(use_r.sum())
        if nl + nr == 0:
            # nothing to reject (every line given by its pixels)
            break
        re = r[: nl + nr]
        robust = max(1.0, 1.4826 * float(_median(np.abs(re - _median(re)))))
        bad = np.abs(re) > settings.reject_sigma * robust
        if not bad.any():
            break
        idx_l, idx_r = np.flatnonzero(use_l), np.flatnonzero(use_r)
        rejected_l[idx_l[bad[:nl]]] = True
        rejected_r[idx_r[bad[nl:]]] = True
        n_rejected += int(bad.sum())
    if level_partial[0] and sel_solved is not None:
        # an unfinished levelled solve (J^T r != 0) would mix its own step into the test's
        verdict = _partial_verdict(model_at(x[:6]), sel_solved, r, J, tables, settings, t, float(x[0])) if status > 0 else "disagree"
        if verdict in ("disagree", "one_end"):
            # the fit with those lines loose, from the start (its outlier
            # rounds and its path along the weak V.z direction would
            # otherwise depend on the levelled fit's)
            loose = fit_motion(camera, edges, initial, replace(settings, area_partial_check=0.0))
            return replace(loose, n_iterations=loose.n_iterations + n_total, run_time_s=time.perf_counter() - t0, partial_verdict=verdict)
    n_iter = n_total
    use_l, use_r, use_a, sl, sr, sa = sel[:6]
    fit_b = len(x) == 7
    n_par = 6 + int(fit_b)
    x_sol = x
    th, b = x_sol[:6], (x_sol[6] if fit_b else 0.0)
    if sel_solved is None:
        return _degenerate_result(initial, edge_lines(sel), settings, use_l, use_r, use_a, t0)
    # r and J belong to the last solved selection (a later re-selection that
    # left too few edges is not used)
    sel = sel_solved
    use_l, use_r, use_a, sl, sr, sa = sel[:6]
    levelled = (level_partial[0] or settings.area_level_partial) and bool(_partial_lines(use_a, model_at(th), tables).any())
    # the pixel windows' (or ends') free brightnesses are parameters too
    dof = r.size - n_par - (0 if sel[-1] is None else sel[-1]["n_groups"])
    chi2_red = float(np.sum(r * r) / dof) if dof > 0 else math.nan
    nl, nr = int(use_l.sum()), int(use_r.sum())
    inflation = 1.0
    if settings.correlation_inflation:
        # only a significant correlation (2 sigma of white noise's rho) counts
        rho = max(_lag_one(r[:nl]) - 2.0 / math.sqrt(max(nl, 1)), _lag_one(r[nl : nl + nr]) - 2.0 / math.sqrt(max(nr, 1)), 0.0)
        inflation = min((1.0 + rho) / (1.0 - rho), 10.0) if rho > 0 else 1.0
    block = _block_scale(r[:nl], r[nl : nl + nr]) if settings.correlation_inflation else 1.0
    chi_scale = max(1.0, chi2_red if np.isfinite(chi2_red) else 1.0)
    total_scale = max(chi_scale * inflation, block)
    inflation = total_scale / chi_scale
    # Column-equilibrated normal matrix: the parameters' sizes differ by 1e8,
    # so the rank test and the inverse are done on unit-norm columns.
    Jw = J
    cn = np.linalg.norm(Jw, axis=0)
    cn = np.where(cn > 0, cn, 1.0)
    N = (Jw / cn).T @ (Jw / cn)
    evals, evecs = np.linalg.eigh(N)
    undetermined: list[str] = []
    tiny = evals < 1e-10 * max(evals.max(), 1e-300)
    if np.any(tiny):
        weight = (evecs[:, tiny] ** 2).sum(axis=1)
        undetermined = [PARAM_NAMES[k] for k in range(6) if weight[k] > 1e-3]
    inv_evals = np.where(tiny, 0.0, 1.0 / np.where(tiny, 1.0, evals))
    cov_s = (evecs * inv_evals) @ evecs.T
    cov_full = cov_s / np.outer(cn, cn) * total_scale
    cov = cov_full[:6, :6].copy()
    for name in undetermined:
        k = PARAM_NAMES.index(name)
        cov[k, :] = np.nan
        cov[:, k] = np.nan
    edge_res = np.concatenate([r[:nl] * sl, r[nl : nl + nr] * sr])
    rms = float(np.sqrt(np.mean(edge_res**2))) if edge_res.size else math.nan
    # report V.x >= 0 unless the crossing is known (the image cannot tell; geometry.md)
    th = th.copy()
    sign = camera.crossing_sign if camera.crossing is not None else 1.0
    if np.sign(th[3]) != sign and not np.any(acc):
        th[3] = -th[3]
        cov[3, :] *= -1
        cov[:, 3] *= -1
    motion = BallMotion.from_params(th, R, acc)
    converged = bool(status > 0)
    flags = []
    if not converged:
        flags.append("not_converged")
    if undetermined:
        flags.append("degenerate")
    return FitResult(
        motion=motion,
        covariance=cov,
        chi2_red=chi2_red,
        residual_rms_px=rms,
        n_iterations=n_iter,
        status=status,
        message=message,
        converged=converged,
        undetermined=tuple(undetermined),
        edge_bias_px=float(b),
        edge_bias_sigma_px=float(math.sqrt(cov_full[6, 6])) if fit_b else 0.0,
        n_edges=nl + nr,
        n_area_lines=int(use_a.sum()),
        run_time_s=time.perf_counter() - t0,
        flags=tuple(flags),
        n_rejected=n_rejected,
        inflation=inflation,
        partial_levelled=levelled,
        partial_verdict=verdict,
    )


def _pinv_sym(a: np.ndarray) -> np.ndarray:
    """Pseudo-inverse of a small symmetric positive semi-definite matrix (eigenvalues below 1e-10 of the largest dropped)."""
    w, v = np.linalg.eigh(a)
    inv = np.where(w > 1e-10 * max(float(w.max()), 1e-300), 1.0 / np.where(w > 0, w, 1.0), 0.0)
    return (v * inv) @ v.T


def _partial_lines(use_a: np.ndarray, me: ModelEdges, tables: dict) -> np.ndarray:
    """Area lines seen during part of the exposure (model presence in (0, 0.999)) that have a level."""
    pres = me.presence[0]
    return use_a & (pres > 0) & (pres < 0.999) & tables["levelled"]


def _at_both_ends(lines: np.ndarray, t_s: np.ndarray, t_c_s: float) -> bool:
    """Whether the mask ``lines`` holds lines both before and after ``t_c_s`` (line times ``t_s``)."""
    return bool(on_both_sides(as_arg(lines, np.bool_), as_arg(t_s), float(t_c_s)))


def _partial_verdict(me: ModelEdges, sel, r: np.ndarray, J: np.ndarray, tables: dict, settings: "FitSettings", t_s: np.ndarray, t_c_s: float) -> str:
    """Whether the levelled areas of the partial lines may stay in the fit (``area_partial_check``).

    ``sel``, ``r`` and ``J`` are the solved selection with those lines
    levelled, its whitened residuals and Jacobian at the solution ``me``.
    The loose fit (those lines' plain areas, :attr:`FitSettings.area_rel_sigma`)
    is one Gauss-Newton step away: from there each levelled area must lie
    within ``area_partial_check`` sigma of the model (its own sigma and the
    loose fit's prediction's in quadrature), and the move between the two
    solutions must pass a Hausman test at the false-alarm rate
    ``partial_shift_p``: with the added lines consistent it has the
    covariance ``C_loose - C_levelled``.  Both ends of the ball need such
    lines: a ball cut by the first or last line has one end, which then
    fixes ``t_c``, V.x and V.z nearly alone (on the POV-Ray scene of such a
    ball its levelled last lines moved the speed by up to 4 %).  Both tests
    use the fits' unscaled sigmas (no reduced chi-square or correlation
    inflation), so on real images they fail more often than
    ``partial_shift_p`` says; failing only costs the loose fit.

    Returns
    -------
    str
        ``"none"`` (no partial line is levelled), ``"one_end"``, ``"agree"``
        or ``"disagree"``.
    """
    use_l, use_r, use_a = sel[:3]
    sa = sel[5]
    partial = _partial_lines(use_a, me, tables)
    if not partial.any():
        return "none"
    if not _at_both_ends(partial, t_s, t_c_s):
        return "one_end"
    pa = np.flatnonzero(partial[use_a])  # among the area rows
    rows = int(use_l.sum() + use_r.sum()) + pa
    lines = np.flatnonzero(use_a)[pa]
    model = me.area_px[0][lines]
    # those rows loose (the model's area derivatives, pixels, over the loose
    # sigmas), both Jacobians equilibrated by the loose one's column norms
    r_l, Jl_n, Jt_n, gn = loose_rows(
        as_arg(J), as_arg(r), rows, as_arg(sa[pa]), as_arg(tables["sa"][lines]), as_arg(model), as_arg(tables["ma"][lines])
    )
    c_l, c_t = _pinv_sym(Jl_n.T @ Jl_n), _pinv_sym(Jt_n.T @ Jt_n)
    step = -c_l @ (Jl_n.T @ r_l)  # to the loose solution (equilibrated parameters)
    pred = model + gn @ step
    var_pred = np.einsum("ij,jk,ik->i", gn, c_l, gn)
    z = (pred - tables["ma_lev"][lines]) / np.sqrt(tables["sa_lev"][lines] ** 2 + var_pred)
    if not np.all(np.abs(z) <= settings.area_partial_check):
        return "disagree"
    diff = c_l - c_t
    w, v = np.linalg.eigh(0.5 * (diff + diff.T))
    keep = w > 1e-9 * max(float(w.max()), 1e-300)
    if not keep.any():
        return "agree"
    d = v[:, keep].T @ step
    stat = float(np.sum(d * d / w[keep]))
    return "agree" if stat <= float(chdtri(int(keep.sum()), settings.partial_shift_p)) else "disagree"


def _pixel_spec(
    edges: EdgeMeasurements, me: ModelEdges, end_p: np.ndarray, spread_p: np.ndarray, t_c: float, settings: "FitSettings"
) -> dict | None:
    """Pixels to fit: the end lines' segments and the spread lines' edge windows.

    ``end_p`` lines (no usable edge pair) give one window over the model's
    segment and the measured signal, 4 pixels more on each side; ``spread_p``
    lines give a window around each model edge reaching ``spread / 2 +
    pixel_window_px`` pixels to either side (one window when the two meet).
    Every window (``pixel_groups="window"``) or every end of the ball
    (``"end"``: before / after ``t_c``) has its own free brightness.  The
    model of a pixel is that brightness times the ball's relative surface
    brightness there (``edges.profile_shade``; 1 without a shading model)
    times its averaged coverage.  Returns None when no pixel is usable.
    """
    idx = np.flatnonzero(end_p | spread_p)
    if idx.size == 0:
        return None
    prof = edges.profile[idx]
    psig = edges.profile_sigma[idx]
    C = prof.shape[1]
    c0 = edges.profile_col0
    cols = c0 + np.arange(C, dtype=float)
    L, Rr, sp = me.left_px[idx], me.right_px[idx], me.spread_px[idx]
    sp = _nan_to_zero(sp)
    sig_px = prof > 3.0 * psig  # (False where NaN)
    seg_lo = np.minimum(L, np.where(sig_px.any(1), cols[np.argmax(sig_px, axis=1)], np.inf)) - 4.0
    seg_hi = np.maximum(Rr, np.where(sig_px.any(1), cols[C - 1 - np.argmax(sig_px[:, ::-1], axis=1)], -np.inf)) + 4.0
    reach = sp / 2.0 + settings.pixel_window_px
    is_end = end_p[idx][:, None]
    cc = cols[None, :]
    in_left = np.abs(cc - L[:, None]) <= reach[:, None]
    in_right = np.abs(cc - Rr[:, None]) <= reach[:, None]
    mask = np.where(is_end, (cc >= seg_lo[:, None]) & (cc <= seg_hi[:, None]), in_left | in_right)
    mask &= np.isfinite(prof) & (psig > 0)
    # compact: the usable columns of each line, left-aligned (row-major
    # nonzero keeps each line's columns in order)
    n_col = mask.sum(axis=1)
    keep = n_col > 0
    if not keep.any():
        return None
    idx, mask, prof, psig = idx[keep], mask[keep], prof[keep], psig[keep]
    n_col = n_col[keep]
    K = int(n_col.max())
    rows, ci = np.nonzero(mask)
    pos = np.arange(rows.size) - np.repeat(np.cumsum(n_col) - n_col, n_col)
    m = np.zeros((idx.size, K), dtype=bool)
    m[rows, pos] = True

    def packed(values, fill):
        out = np.full((idx.size, K), fill, dtype=values.dtype)
        out[rows, pos] = values
        return out

    # the unused slots: the line's first usable column, no weight, no value
    cols_k = packed(cols[ci], 0.0)
    cols_k = np.where(m, cols_k, cols_k[:, :1])
    shade = edges.profile_shade[idx][rows, ci] if edges.profile_shade is not None else np.ones(rows.size)
    shade = np.where(np.isfinite(shade) & (shade > 0), shade, 1.0)
    s_u = psig[rows, ci]
    w = 1.0 / np.sqrt(np.where(s_u > 0, s_u, 1.0) ** 2 + settings.pixel_floor**2)
    if settings.pixel_groups == "end":
        g = (edges.t_s[idx] > t_c).astype(np.int64)[rows]
    else:
        # windows: 0 the left (or only) one of a line, 1 the right one where the two are apart
        L, Rr, reach, is_end = L[keep], Rr[keep], reach[keep], is_end[keep, 0]
        apart = ((L + reach) < (Rr - reach)) & ~is_end
        g = 2 * rows + (apart[rows] & (cols[ci] > 0.5 * (L + Rr)[rows]))
    # dense group numbers in the order of the groups' labels
    present = np.zeros(int(g.max()) + 1, dtype=np.int64)
    present[g] = 1
    g_dense = (np.cumsum(present) - 1)[g]
    return dict(
        t=edges.t_s[idx],
        cols=cols_k,
        mask=m,
        p=packed(prof[rows, ci], 0.0),  # finite (the mask)
        w=packed(w, 0.0),
        shade=packed(shade, 1.0),
        group=packed(g_dense.astype(np.int64), np.int64(-1)),
        n_groups=int(g_dense.max()) + 1,
        n=int(rows.size),
        n_spread=int(spread_p[idx].sum()),
        nodes=settings.pixel_nodes,
    )


def pixel_coverage(u_lo: np.ndarray, u_hi: np.ndarray, wgt: np.ndarray, cols: np.ndarray) -> np.ndarray:
    """Averaged coverage of pixels by the model's chord samples.

    Parameters
    ----------
    u_lo, u_hi, wgt : ndarray (P, N, 3, n)
        Chord ends (pixels) and weights of each sample of each line
        (``samples`` of :func:`averaged_model` with ``return_samples``).
    cols : ndarray (C,) or (N, C)
        Pixel centres (pixels), shared by the lines or one row per line; a
        pixel spans ``[col - 1/2, col + 1/2]``.

    Returns
    -------
    ndarray (P, N, C)
        Sum over the samples of weight times the overlap of ``[lo, hi]``
        with the pixel; NaN on a line with a NaN sample.

    Notes
    -----
    Where a line's pixel centres lie on a grid of unit step (any order, gaps
    allowed: an edge's offsets, the fit's compacted windows, a bound's
    columns) the sum is a histogram of the samples' ends by pixel and its
    cumulative sum (:func:`ballscan.model._forward_kernels.coverage_grid`): O(samples +
    pixels) per line.  Other centres take the direct sum over samples and
    pixels.
    """
    c = np.asarray(cols, dtype=float)
    lead = u_lo.shape[:-2]
    P, N = int(np.prod(lead[:-1])), lead[-1]
    c2 = np.broadcast_to(c, (N, c.shape[-1]))
    if c2.shape[-1] == 0 or not np.all(np.isfinite(c2)):
        return _pixel_coverage_direct(u_lo, u_hi, wgt, c)
    base = c2.min(axis=1)
    rel = c2 - base[:, None]
    idx = np.rint(rel)
    if not np.all(np.abs(rel - idx) < 1e-9):
        return _pixel_coverage_direct(u_lo, u_hi, wgt, c)
    idx = as_arg(idx, np.int64)
    shp = (P, N, -1)
    out = coverage_grid(*(as_arg(a.reshape(shp)) for a in (u_lo, u_hi, wgt)), idx, as_arg(base), int(idx.max()) + 1)
    return out.reshape(lead + (c2.shape[-1],))


def _pixel_coverage_direct(u_lo: np.ndarray, u_hi: np.ndarray, wgt: np.ndarray, cols: np.ndarray) -> np.ndarray:
    """:func:`pixel_coverage` as the direct sum over samples and pixels (any pixel centres; the reference of the grid's)."""
    a = np.asarray(cols, dtype=float) - 0.5
    if a.ndim == 2:
        a = a[:, None, None, :]
    ov = np.clip(np.minimum(u_hi[..., None], a + 1.0) - np.maximum(u_lo[..., None], a), 0.0, 1.0)
    return (wgt[..., None] * ov).sum(axis=(-3, -2))


def _pixel_residuals(camera, thetas: np.ndarray, R: float, pix: dict, acc, n_nodes: int) -> np.ndarray:
    """Whitened residuals ``(B_g s cov - p) / sigma`` of the fitted pixels, (P, M).

    ``cov`` is each pixel's coverage averaged over the exposure and the
    pixel's height (``pixel_nodes`` Gauss-Legendre nodes per piece), ``s``
    the ball's relative surface brightness there and ``B_g`` the brightness
    of the pixel's window (or end), the least-squares value for each
    parameter set (variable projection): the coverage's shape counts, the
    local level comes from the pixels.
    """
    # (the samples only: no edge spread or validity)
    me = _model_core(camera, thetas, R, pix["t"], acc, max(n_nodes, pix["nodes"]), True, full=False)
    P, n_rows = thetas.shape[0], pix["cols"].shape[0]
    u_lo, u_hi, wgt = (as_arg(a.reshape(P, n_rows, -1)) for a in me.samples)
    return _kernel_pixel_residuals(
        u_lo, u_hi, wgt, pix["cols"], pix["mask"], pix["shade"], pix["w"], pix["p"], pix["group"], pix["n_groups"], pix["n"]
    )


def _pixel_residuals_jacobian(camera, theta: np.ndarray, R: float, pix: dict, n_nodes: int) -> np.ndarray:
    """Exact derivatives (M, 6) of :func:`_pixel_residuals` at one parameter set ``theta`` (no acceleration).

    One compiled pass (:func:`ballscan.model._forward_kernels.pixel_residuals_jacobian`)
    in place of six perturbed evaluations of the samples and the coverage.
    """
    g, gw = _gauss(max(n_nodes, pix["nodes"]))
    _, J = _kernel_pixel_residuals_jacobian(
        as_arg(theta), as_arg(pix["t"]), float(R), float(camera.exposure), float(camera.focal_px), float(camera.principal_px),
        float(camera.k1), float(camera.k2), as_arg(g), as_arg(gw),
        pix["cols"], pix["mask"], pix["shade"], pix["w"], pix["p"], pix["group"], pix["n_groups"], pix["n"],
    )
    return J


def _block_scale(*sides: np.ndarray, sizes=(4, 8, 16)) -> float:
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


def _lag_one(r: np.ndarray) -> float:
    """Lag-one autocorrelation of a residual sequence (0 for fewer than 3)."""
    if r.size < 3:
        return 0.0
    d = r - r.mean()
    den = float(d @ d)
    return float(d[:-1] @ d[1:]) / den if den > 0 else 0.0


def _weights_masked(
    edges: EdgeMeasurements, use_l, use_r, use_a, settings: FitSettings, wide_l=None, wide_r=None, tables=None, loose_a=None
):
    """Measured values and 1-sigma (pixels) of the selected residuals.

    Returns ``(use_l, use_r, use_a, sl, sr, sa, ml, mr, ma)``: the masks, the
    sigmas and the measurements of the left edges, right edges and areas;
    edges in ``wide_l`` / ``wide_r`` come from the wide window; areas of
    lines in ``loose_a`` are not levelled (see :func:`_area_tables`).
    ``tables`` (from :func:`_weight_tables`, same ``edges`` and
    ``settings``) gives the same result from per-line values computed once.
    """
    T = tables if tables is not None else _weight_tables(edges, settings)
    n = edges.lines.size
    wl = np.zeros(n, dtype=bool) if wide_l is None or not T["has_wide"] else wide_l
    wr = np.zeros(n, dtype=bool) if wide_r is None or not T["has_wide"] else wide_r
    lev = T["levelled"] if loose_a is None else T["levelled"] & ~loose_a
    return (
        use_l,
        use_r,
        use_a,
        np.where(wl, T["sl_w"], T["sl_n"])[use_l],
        np.where(wr, T["sr_w"], T["sr_n"])[use_r],
        np.where(lev, T["sa_lev"], T["sa"])[use_a],
        np.where(wl, T["el_w"], T["el_n"])[use_l],
        np.where(wr, T["er_w"], T["er_n"])[use_r],
        np.where(lev, T["ma_lev"], T["ma"])[use_a],
    )


def _nan_to_zero(a: np.ndarray) -> np.ndarray:
    """``a`` with NaN as 0 (``np.nan_to_num`` without its infinities' clipping, at a third of its cost)."""
    return np.where(np.isnan(a), 0.0, a)


def _weight_tables(edges: EdgeMeasurements, settings: FitSettings) -> dict:
    """Per-line measurements and 1-sigma of :func:`_weights_masked`, for both windows (pixels).

    The same arithmetic on every line, done once per fit; selecting from
    these tables gives exactly :func:`_weights_masked`'s values.
    """
    n = edges.lines.size
    floor2 = settings.edge_floor_px**2
    # matched edges (edges.matched_edges) have their own, smaller floor
    floor2_l = np.where(edges.left_matched, settings.matched_floor_px**2, floor2) if edges.left_matched is not None else floor2
    floor2_r = np.where(edges.right_matched, settings.matched_floor_px**2, floor2) if edges.right_matched is not None else floor2
    g = settings.texture_gain
    tl = edges.left_texture_px if edges.left_texture_px is not None else np.zeros(n)
    tr = edges.right_texture_px if edges.right_texture_px is not None else np.zeros(n)
    tex_l = (g * _nan_to_zero(tl)) ** 2
    tex_r = (g * _nan_to_zero(tr)) ** 2
    has_wide = edges.left_wide_px is not None
    T = dict(
        has_wide=has_wide,
        el_n=edges.left_px,
        er_n=edges.right_px,
        sl_n=np.sqrt(_nan_to_zero(edges.left_sigma_px) ** 2 + floor2_l + tex_l),
        sr_n=np.sqrt(_nan_to_zero(edges.right_sigma_px) ** 2 + floor2_r + tex_r),
    )
    if has_wide:
        T.update(
            el_w=edges.left_wide_px,
            er_w=edges.right_wide_px,
            sl_w=np.sqrt(_nan_to_zero(edges.left_wide_sigma_px) ** 2 + floor2 + tex_l),
            sr_w=np.sqrt(_nan_to_zero(edges.right_wide_sigma_px) ** 2 + floor2 + tex_r),
        )
    else:
        T.update(el_w=T["el_n"], er_w=T["er_n"], sl_w=T["sl_n"], sr_w=T["sr_n"])
    ma = _area_levelled(edges, settings)
    T["ma"] = ma
    T["sa"] = np.sqrt(edges.area_sigma_px**2 + (settings.area_rel_sigma * np.maximum(ma, 0.0)) ** 2 + settings.area_floor_px**2)
    T["ma_lev"], T["sa_lev"], T["levelled"] = _area_tables(edges, settings)
    return T


def _area_tables(edges: EdgeMeasurements, settings: FitSettings) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Covered lengths of the lines with a model level, their 1-sigma (pixels) and where they exist.

    ``area_px / area_level``: the level is the brightness model's mean over
    the line's covered part (:attr:`ballscan.measure.edges.EdgeMeasurements.area_level`),
    so the quotient is the covered length the silhouette model predicts.
    Its sigma: the area's pixel noise and the level's relative sigma
    (texture, in quadrature with ``area_level_floor``) times the length,
    plus ``area_level_floor_px``.
    """
    n = edges.lines.size
    if edges.area_level is None:
        z = np.zeros(n)
        return z, z, np.zeros(n, dtype=bool)
    # one compiled pass over the lines (:func:`ballscan.solve._fit_kernels.area_tables`)
    return area_tables(
        as_arg(edges.area_px), as_arg(edges.area_sigma_px), as_arg(edges.area_level), as_arg(edges.area_level_sigma),
        settings.area_level_floor**2, settings.area_level_floor_px**2,
    )


def _area_levelled(edges: EdgeMeasurements, settings: FitSettings) -> np.ndarray:
    """Summed coverage of each line, optionally divided by the local brightness (pixels).

    ``area_px`` is normalised by the ball's global contrast, but an end line
    shows the ball's cap, whose brightness follows the lighting of that side
    of the ball.  With ``settings.level_areas`` every line with signal is
    divided by the median local inner level
    (:attr:`ballscan.measure.edges.EdgeMeasurements.level`) of the
    ``settings.level_lines`` nearest lines that have one.  Off by default:
    on the reference scenes the inner level next to the limb is itself
    shaded and blurred at the ball's ends, and dividing by it over-corrects.
    """
    area = np.asarray(edges.area_px, dtype=float)
    if not settings.level_areas:
        return area
    lev = np.asarray(edges.level, dtype=float)
    have = np.flatnonzero(np.isfinite(lev) & (lev > 0))
    if have.size == 0:
        return area
    out = area.copy()
    k = max(int(settings.level_lines), 1)
    for i in np.flatnonzero(edges.signal):
        near = have[np.argsort(np.abs(have - i), kind="stable")[:k]]
        L = float(_median(lev[near]))
        if 0.2 < L < 5.0:
            out[i] = area[i] / L
    return out


def _degenerate_result(initial, n_edge_lines, settings, use_l, use_r, use_a, t0) -> "FitResult":
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
        n_edges=int(use_l.sum() + use_r.sum()),
        n_area_lines=int(use_a.sum()),
        run_time_s=time.perf_counter() - t0,
        flags=("degenerate",),
    )


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
        ``speed^2 = sum_k max(a_k^2 - lambda_k, 0)``: each ``a_k^2 - lambda_k``
        is an unbiased estimate of the true ``(Q^T V_true)_k^2`` and the
        positive part (a square cannot be negative) only lowers its error.
        Only the poorly determined direction (chiefly ``vz``) is changed
        noticeably; when its true component is about its own sigma the
        corrected speed is biased low (a reference serve: -0.8 % with
        ``sigma_vz`` 10 m/s on ``vz`` -5.5 m/s).  The sigma is linear in the
        two well-determined directions plus, for the weakest one, the RMS
        distance of the corrected speed to the speeds whose weak component
        lies about its corrected value within its sigma (24-node
        Gauss-Hermite): not only the linear term when the measured component
        is near 0 while the truth may lie a sigma out.  Where the weak
        direction dominates it overstates the RMS error (up to 1.81x in a
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
        ``psi_y = atan2(vy, vx)`` and ``psi_z = atan2(vz, vx)``, degrees.
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


_GH_X, _GH_W = np.polynomial.hermite_e.hermegauss(24)
_GH_W = _GH_W / _GH_W.sum()


def _debiased_speed(V: np.ndarray, Cv: np.ndarray, at_truth: bool = False) -> tuple[float, float]:
    """Bias-corrected speed and its mean squared error (see :class:`MotionUncertainty`).

    In the eigenbasis of ``Cv`` each ``a_k^2 - lambda_k`` estimates the true
    ``a_k^2`` without bias; the positive part keeps it a square.  The error of
    the well-determined directions is linear (``sum (a_k / s)^2 lambda_k``);
    that of the weakest direction is not (its noise can exceed its value), so
    its mean squared error is integrated over ``a ~ N(mu, lambda)``
    (Gauss-Hermite, 24 nodes).  For a measured ``V``, ``mu^2`` is the
    plug-in estimate ``max(a^2 - lambda, 0)`` and ``a`` a true component the
    measurement allows: the integral is the squared distance of this speed
    to the true speeds with those ``a``.  With ``at_truth`` (``V`` the true
    velocity) ``mu = a`` and ``a`` a new measurement: the error a
    measurement of covariance ``Cv`` would make, e.g. for a bound.

    Returns ``(speed, mse)``: the corrected speed of ``V`` (``|V|`` with
    ``at_truth``) and the mean squared error, (m/s, (m/s)^2).
    """
    lam, Q = np.linalg.eigh(Cv)
    lam = np.maximum(lam, 0.0)
    a = Q.T @ V
    sq = a * a if at_truth else np.maximum(a * a - lam, 0.0)
    speed = float(np.sqrt(sq.sum()))
    w = int(np.argmax(lam))
    strong = np.arange(3) != w
    s_strong2 = float(sq[strong].sum())
    # d speed / d a_k = a_k / speed; where the correction removed (nearly)
    # everything the derivative is taken at the uncorrected strong part, and
    # with no signal at all the noise's total is the error's scale
    denom = max(speed * speed, float(np.sum(a[strong] ** 2)))
    if denom <= 0.0:
        return speed, float(np.sum(lam))
    var_strong = float(np.sum(a[strong] ** 2 * lam[strong])) / denom
    mu = math.sqrt(sq[w])
    draws = mu + math.sqrt(lam[w]) * _GH_X
    if at_truth:
        # the estimator's error over new measurements of the truth mu
        est = np.sqrt(s_strong2 + np.maximum(draws * draws - lam[w], 0.0))
        mse_weak = float(_GH_W @ (est - math.sqrt(s_strong2 + mu * mu)) ** 2)
    else:
        # this estimate's distance to the true speeds that the measurement
        # allows (weak component about mu within its sigma): taken at mu
        # alone, a measured component near 0 would claim the speed to the
        # linear term although the truth may lie a sigma out (a table-tennis
        # scene: errors of 4 sigma in 15 % of the noisy renders)
        mse_weak = float(_GH_W @ (speed - np.sqrt(s_strong2 + draws * draws)) ** 2)
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
    vx = V[0]
    Jd = np.zeros((2, 3))
    for row, comp in ((0, 1), (1, 2)):
        den = vx * vx + V[comp] ** 2
        Jd[row, 0] = -V[comp] / den
        Jd[row, comp] = vx / den
    Cd = Jd @ Cv @ Jd.T
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
        direction_sigma_deg=np.degrees(np.sqrt(np.diag(Cd))),
    )
    if camera.has_pose:
        Rm = camera.rotation_matrix
        out["world_position_m"] = camera.camera_to_world(np.asarray(motion.position_m))
        out["world_position_sigma_m"] = np.sqrt(np.diag(Rm.T @ Cp @ Rm))
        out["world_velocity_mps"] = camera.vectors_to_world(V)
        out["world_velocity_sigma_mps"] = np.sqrt(np.diag(Rm.T @ Cv @ Rm))
    return MotionUncertainty(**out)


# ------------------------------------------------------------ synthetic data


def synthetic_edges(
    camera: LineScanCamera,
    motion: BallMotion,
    n_lines: int,
    edge_sigma_px: float = 0.0,
    seed: int | None = 0,
    area_sigma_px: float = 0.3,
    max_spread_px: float = 0.3,
    add_noise: bool = True,
) -> EdgeMeasurements:
    """Edge measurements generated from the averaged model plus Gaussian noise.

    Lines with presence 1 and edge spread below ``max_spread_px`` get edges
    (sigma ``edge_sigma_px``); the others get only the model area with noise
    ``area_sigma_px`` (pixels).  For tests and precision studies.
    """
    rng = np.random.default_rng(seed)
    k_noise = 1.0 if add_noise else 0.0
    t = np.arange(n_lines) / camera.line_rate_hz
    me = averaged_model(camera, motion.to_params()[None], motion.radius_m, t, motion.acceleration_mps2, 8)
    left, right, pres, area, spread = me.left_px[0], me.right_px[0], me.presence[0], me.area_px[0], me.spread_px[0]
    ok = (pres > 0.999) & (spread <= max_spread_px) & me.valid[0]
    # keep the ball's lines plus two on each side
    idx = np.flatnonzero(pres > 0)
    if idx.size == 0:
        raise ValueError("synthetic_edges: the ball is not seen on any line")
    keep = slice(max(idx[0] - 2, 0), min(idx[-1] + 3, n_lines))
    t, left, right, pres, area, spread, ok = (a[keep] for a in (t, left, right, pres, area, spread, ok))
    lines = np.arange(n_lines)[keep]
    n = t.size
    el = left + k_noise * edge_sigma_px * rng.standard_normal(n)
    er = right + k_noise * edge_sigma_px * rng.standard_normal(n)
    ar = area + k_noise * area_sigma_px * rng.standard_normal(n)
    sig = np.full(n, float(edge_sigma_px))
    end = (pres > 0) & ~ok
    return EdgeMeasurements(
        lines=lines,
        t_s=t,
        left_px=np.where(ok, el, np.nan),
        right_px=np.where(ok, er, np.nan),
        left_sigma_px=np.where(ok, sig, np.nan),
        right_sigma_px=np.where(ok, sig, np.nan),
        left_ok=ok.copy(),
        right_ok=ok.copy(),
        area_px=ar,
        area_sigma_px=np.full(n, float(area_sigma_px)),
        centroid_px=np.where(pres > 0, 0.5 * (left + right), np.nan),
        level=np.where(ok, 1.0, np.nan),
        peak=np.where(pres > 0, 1.0, 0.0),
        end_line=end,
    )
