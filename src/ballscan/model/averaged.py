"""The averaged silhouette model of many parameter sets at once, and its Jacobians.

The model is the paper's dynamic sphere (Zhao & Wen, first Eq. (8))
projected by the line-scan camera of Eq. (1)-(2) and averaged over a pixel's
height and the exposure, as in :func:`ballscan.model.silhouette.silhouette`
with ``model="averaged"``; here it is broadcast over a leading axis of
parameter sets ``theta = (t_c, y0, z0, vx, vy, vz)``
(:data:`ballscan.geometry.motion.PARAM_NAMES`; s, m, m, m/s, m/s, m/s) and
evaluated by one compiled loop (:func:`ballscan.model._forward_kernels.averaged_samples`).

Its derivatives with respect to ``theta`` (the refinement's Jacobian,
Eq. (7)-(10)):

* :func:`chord_jacobian`: closed-form derivatives of the chord model's
  edges (the viewing plane ``x = 0`` at the line's centre time);
* :func:`model_jacobian`: forward differences of the averaged model, all
  perturbed parameter sets in one call;
* :func:`hybrid_jacobian`: the chord's derivatives on the lines well inside
  the ball's crossing, the averaged model's exact (forward-mode) or
  finite-difference derivatives at the ball's ends.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..compiled import as_arg
from ._forward_kernels import averaged_samples, chord_edges, hybrid_rows
from ..geometry.camera import LineScanCamera
from ..geometry.motion import BallMotion
from .blur import ACROSS_NODES, blur_diameter, semicircle_nodes
from .silhouette import _gauss

__all__ = [
    "JacobianMemo",
    "ModelEdges",
    "ModelEvaluator",
    "averaged_model",
    "chord_jacobian",
    "hybrid_jacobian",
    "model_jacobian",
]


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
        ``(u_lo, u_hi, weight)`` per sample, each (P, N, 3 B, n), when asked
        for (B the blur's offsets across the sensor, :func:`blur_offsets`).
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
    reach = np.abs(c[:, 0]) + vx * camera.exposure / 2 + np.maximum(c[:, 2], 0.0) * _height_reach(camera)
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
    (P, N, 3 B, n_nodes) (B the blur's offsets, :func:`blur_offsets`): for
    each, three pieces of ``n_nodes`` Gauss-Legendre nodes
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
    blur = _blur_args(camera)
    left, right, presence, area, spread, valid, u_lo, u_hi, wgt = averaged_samples(
        th, t, *_kernel_args(camera, R, acceleration_mps2, n_nodes), bool(full), bool(return_samples), *blur
    )
    samples = None
    if return_samples:
        shp = left.shape + (3 * blur[0].size, n_nodes)
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


def blur_offsets(camera: LineScanCamera) -> tuple[np.ndarray, np.ndarray]:
    """The offsets across the sensor (pixels) and weights that carry the camera's blur circle into the model; ``([0], [1])`` in focus.

    The blur circle's marginal across the sensor
    (:func:`ballscan.model.blur.semicircle_nodes`, :data:`ballscan.model.blur.ACROSS_NODES`)
    widens the pixel's height, which the averaged silhouette integrates in
    closed form between kinks; each offset is one such pixel, its viewing
    plane moved by the offset at the line's depth.
    """
    return semicircle_nodes(blur_diameter(camera), ACROSS_NODES)


def _height_reach(camera: LineScanCamera) -> float:
    """How far a line sees across the sensor, per metre of depth (m/m): the pixel's half height and the blur circle's radius."""
    return (0.5 + 0.5 * blur_diameter(camera)) / camera.focal_px


def _kernel_args(camera, R, acceleration_mps2, n_nodes) -> tuple:
    """:func:`ballscan.model._forward_kernels.averaged_samples`' arguments after the line times: radius, camera, acceleration, nodes."""
    g, gw = _gauss(n_nodes)
    return (
        float(R), float(camera.exposure), float(camera.focal_px), float(camera.principal_px), float(camera.k1), float(camera.k2),
        np.array([float(a) for a in acceleration_mps2]), as_arg(g), as_arg(gw),
    )


def _blur_args(camera) -> tuple[np.ndarray, np.ndarray]:
    """:func:`ballscan.model._forward_kernels.averaged_samples`' last arguments: the blur's offsets and weights (:func:`blur_offsets`)."""
    return tuple(as_arg(a) for a in blur_offsets(camera))


class ModelEvaluator:
    """``averaged_model(camera, th, R, t_lines_s, acceleration_mps2, n_nodes)`` as a callable of ``th`` (P, 6).

    A fit evaluates the model at the same lines several times per ball: with
    ``n_nodes <= 3`` (one kernel call on every line) the fixed arguments are
    converted once, here.

    Parameters
    ----------
    camera : LineScanCamera
    radius_m : float
        Ball radius, m.
    t_lines_s : ndarray (N,)
        Line centre times, s.
    acceleration_mps2 : sequence of 3 floats
        Known acceleration, m/s^2.
    n_nodes : int
        Gauss-Legendre nodes per piece.
    """

    __slots__ = ("camera", "radius_m", "t_lines_s", "acceleration_mps2", "n_nodes", "_t", "_args")

    def __init__(self, camera: LineScanCamera, radius_m: float, t_lines_s: np.ndarray, acceleration_mps2, n_nodes: int):
        self.camera, self.radius_m, self.t_lines_s = camera, radius_m, t_lines_s
        self.acceleration_mps2, self.n_nodes = acceleration_mps2, n_nodes
        # the kernel's arguments (only the direct path of n_nodes <= 3 uses them)
        self._t = as_arg(np.asarray(t_lines_s, dtype=float).reshape(1, -1)) if n_nodes <= 3 else None
        self._args = (*_kernel_args(camera, radius_m, acceleration_mps2, n_nodes), True, False, *_blur_args(camera)) if n_nodes <= 3 else None

    def __call__(self, th: np.ndarray) -> ModelEdges:
        """The model (with edge spread and validity) at the parameter sets ``th`` (P, 6)."""
        if self._t is None:
            return averaged_model(self.camera, th, self.radius_m, self.t_lines_s, self.acceleration_mps2, self.n_nodes)
        left, right, presence, area, spread, valid, _, _, _ = averaged_samples(as_arg(th), self._t, *self._args)
        return ModelEdges(left, right, presence, area, spread, valid)


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


@dataclass
class JacobianMemo:
    """Finite-difference rows of :func:`hybrid_jacobian`, kept between its calls within one fit.

    Mutable on purpose: a fit's successive Jacobians reuse the rows taken
    nearby (see ``memo`` of :func:`hybrid_jacobian`).

    Attributes
    ----------
    theta : ndarray (6,) or None
        Parameters at which the stored rows were taken (None: nothing stored).
    n_lines : int
        Number of lines of the stored rows (-1: none).
    have : ndarray of bool (N,)
        Lines whose rows are stored.
    chord_ok : ndarray of bool (N,)
        Where the chord model had edges at ``theta``.
    fd_left, fd_right, fd_area : ndarray (N, 6)
        The stored derivatives of the averaged model, pixels per parameter unit.
    corr_left, corr_right, corr_area : ndarray (N, 6)
        Their differences from the chord derivatives at ``theta``.
    last_fd : ndarray of bool (N,) or None
        Lines that got the averaged model's derivatives in the last call.
    """

    theta: np.ndarray | None = None
    n_lines: int = -1
    have: np.ndarray | None = None
    chord_ok: np.ndarray | None = None
    fd_left: np.ndarray | None = None
    fd_right: np.ndarray | None = None
    fd_area: np.ndarray | None = None
    corr_left: np.ndarray | None = None
    corr_right: np.ndarray | None = None
    corr_area: np.ndarray | None = None
    last_fd: np.ndarray | None = None


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
    memo: JacobianMemo | None = None,
    reuse_px: float = 0.1,
    base: tuple[np.ndarray, np.ndarray, np.ndarray] | None = None,
    analytic: bool = False,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Jacobian of the averaged model: analytic chord derivatives inside, the averaged model's at the ends.

    On a line whose section offsets stay well inside the ball (``|x0| +
    A + B <= reach_limit * R``, with ``A`` the exposure's and ``B`` the pixel
    height's half-width of the offset, see :func:`ballscan.model.silhouette.silhouette`)
    the averaged edge is the chord edge plus a small, smooth correction
    (about half the edge's second derivative in the offset times the
    offset's variance: 0.002-0.005 px there); its derivative is that of the
    chord (:func:`chord_jacobian`) to 0.1 % of the largest term.  The other
    lines (the ball's ends, where the correction grows, and ``fd_lines``)
    get the averaged model's derivatives: exact ones (``analytic``) or the
    forward differences of :func:`model_jacobian`, in one vectorised call
    over those lines only: on the lines whose section offsets stay inside
    the ball only the ``t_c`` and ``vx`` columns (the correction depends on
    the parameters through ``x0 = vx (t - t_c)``; the other columns' part is
    below 1e-5 of the derivatives), all six on the others (:func:`_fd_rows`).
    These are the derivatives of the refinement's residuals (Eq. (7)-(10)).

    Parameters
    ----------
    camera, theta, radius_m, t_lines_s, scale, acceleration_mps2, rel_step, n_nodes
        As for :func:`model_jacobian`.
    fd_lines : ndarray of bool (N,), optional
        Lines that always get the averaged model's derivatives (e.g. area residuals).
    needed : ndarray of bool (N,), optional
        Lines whose derivatives are used; the others are left at the chord
        derivative (or NaN) without the averaged model's.
    reach_limit : float
        See above; 0 gives the averaged model's derivatives everywhere.
    memo : JacobianMemo, optional
        Filled with the finite differences and their difference from the
        chord derivatives; a later call that needs no new line and whose
        ``theta`` moved the model's edges on those lines by at most
        ``reuse_px`` (to first order) reuses them: the chord derivatives at
        ``theta`` plus the stored correction (the whole stored row where the
        chord has no edge).  The correction is 0.5 % of the derivative at
        most and changes by a small fraction of that over such a move.
        ``memo.last_fd`` is set to the lines of this call's averaged-model rows.
    reuse_px : float
        See ``memo`` (pixels).
    base : tuple of ndarray (N,), optional
        ``(left, right, area)`` of the averaged model at ``theta`` with
        ``n_nodes`` nodes on every line, when the caller has them: the
        finite differences then evaluate only the perturbed sets.
    analytic : bool
        The averaged model's exact derivatives instead of finite differences
        (:func:`ballscan.model._forward_kernels.averaged_edges_jacobian`; without a known
        acceleration or a lens blur, which its forward mode does not know; one
        compiled call with the chord's,
        :func:`ballscan.model._forward_kernels.hybrid_rows`); ``memo`` is then only told
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
    if analytic and not any(acceleration_mps2) and blur_diameter(camera) == 0:
        dl, dr, da, fd = _analytic_rows(camera, theta, t, R, n_nodes, reach_limit, fd_lines, needed)
        if memo is not None:
            memo.last_fd = fd
        return dl, dr, da
    u, J, chord_ok, x0, z, tau = _chord_core(camera, theta, R, t, acceleration_mps2)
    dl, dr = J[0], J[1]
    ax = float(acceleration_mps2[0])
    vxt = np.abs(theta[3] + ax * tau) if ax else abs(float(theta[3]))
    reach = np.abs(x0) + vxt * (camera.exposure / 2.0) + np.maximum(z, 0.0) * _height_reach(camera)
    fd = ~chord_ok | (reach > reach_limit * R)
    if fd_lines is not None:
        fd |= fd_lines
    if needed is not None:
        fd &= needed
    da = dr - dl
    if memo is not None:
        memo.last_fd = fd
    if not fd.any():
        return dl, dr, da
    scale = np.asarray(scale, dtype=float)
    if memo is not None and _reused(memo, theta, t.size, fd, chord_ok, dl, dr, da, reuse_px):
        return dl, dr, da
    h = rel_step * scale
    fl, fr, fa = _fd_rows(camera, theta, R, t, fd, chord_ok & (reach < R), h, dl, dr, acceleration_mps2, n_nodes, base)
    if memo is not None:
        _store(memo, theta, t.size, fd, chord_ok, (fl, fr, fa), (dl, dr, da))
    dl[fd], dr[fd], da[fd] = fl, fr, fa
    return dl, dr, da


def _analytic_rows(camera, theta, t, R, n_nodes, reach_limit, fd_lines, needed):
    """:func:`hybrid_jacobian` with ``analytic``: ``(d_left, d_right, d_area, fd)`` in one compiled call.

    The chord's derivatives, the lines ``fd`` that need the averaged model's
    exact ones, and those (:func:`ballscan.model._forward_kernels.hybrid_rows`).
    """
    g, gw = _gauss(n_nodes)
    no_lines = np.zeros(0, dtype=bool)
    return hybrid_rows(
        as_arg(theta), as_arg(t), R, float(camera.exposure), float(camera.focal_px), float(camera.principal_px),
        float(camera.k1), float(camera.k2), as_arg(g), as_arg(gw), reach_limit * R,
        no_lines if fd_lines is None else as_arg(fd_lines, np.bool_),
        no_lines if needed is None else as_arg(needed, np.bool_),
        fd_lines is not None, needed is not None,
    )


def _reused(memo: JacobianMemo, theta, n_lines, fd, chord_ok, dl, dr, da, reuse_px) -> bool:
    """Whether ``memo``'s rows cover the lines ``fd`` near ``theta``; if so they are applied to ``dl, dr, da`` in place.

    Near means the stored rows move the model's edges on those lines by at
    most ``reuse_px`` pixels (first order) over ``theta - memo.theta``.
    """
    if memo.theta is None or memo.n_lines != n_lines or not memo.have[fd].all():
        return False
    step = theta - memo.theta
    if np.abs(memo.fd_left[fd] @ step).max() > reuse_px or np.abs(memo.fd_right[fd] @ step).max() > reuse_px:
        return False
    # finite differences taken nearby: keep their difference to the chord
    # derivatives (a small, slowly varying correction), or the whole row
    # where the chord has none (lines at or past the ends)
    keep_row = fd & chord_ok & memo.chord_ok
    whole = fd & ~keep_row
    pairs = ((dl, memo.corr_left, memo.fd_left), (dr, memo.corr_right, memo.fd_right), (da, memo.corr_area, memo.fd_area))
    for cur, corr, old in pairs:
        cur[keep_row] += corr[keep_row]
        cur[whole] = old[whole]
    return True


def _store(memo: JacobianMemo, theta, n_lines, fd, chord_ok, rows, chord) -> None:
    """Keep the averaged-model rows ``rows = (fl, fr, fa)`` of lines ``fd`` and their differences from ``chord = (dl, dr, da)``."""
    if memo.n_lines != n_lines:
        for k in ("fd_left", "fd_right", "fd_area", "corr_left", "corr_right", "corr_area"):
            setattr(memo, k, np.zeros((n_lines, 6)))
    (fl, fr, fa), (dl, dr, da) = rows, chord
    memo.fd_left[fd], memo.fd_right[fd], memo.fd_area[fd] = fl, fr, fa
    memo.corr_left[fd], memo.corr_right[fd], memo.corr_area[fd] = fl - dl[fd], fr - dr[fd], fa - da[fd]
    memo.theta, memo.n_lines, memo.have, memo.chord_ok = theta.copy(), n_lines, fd.copy(), chord_ok
