"""The refinement's least-squares problem: residual blocks, their selection and weights, residuals and Jacobian.

The refinement (Zhao & Wen, Eq. (7)-(10)) fits ``x = (t_c, y0, z0, vx, vy,
vz)`` (:data:`ballscan.geometry.motion.PARAM_NAMES`; s, m, m, m/s, m/s,
m/s), optionally followed by a symmetric edge bias ``b`` (pixels, a
"dilation": left edges move by ``-b``, right edges by ``+b``), of the
averaged silhouette (:mod:`ballscan.model.averaged`, the dynamic sphere of
Eq. (8) seen through the camera of Eq. (1)) to measured edges.

A :class:`ResidualBlock` is one camera's measurements; several blocks share
the motion parameters (one ball seen by several cameras).  For each block
a :class:`Selection` names which residuals enter and with which weights
(all whitened by their 1-sigma):

* edge lines: ``left_model - b - left_meas`` and ``right_model + b -
  right_meas`` where the edge is usable (the narrow local-area edges where
  the model's edge spread over the exposure and pixel height is below
  ``max_spread_px``, the wide-window edges up to ``max_spread_wide_px``);
  each edge's sigma is its pixel noise, a systematic floor and its texture
  indicator in quadrature;
* area lines: the lines just outside the ball (``area_model - area_meas``)
  and the ball's end lines, where the chord grows like the square root of
  time: their summed coverage, divided by the shading model's brightness
  of the covered part when the edges carry it, else with a large relative
  sigma (the lit or shaded cap's brightness is unknown); not where the
  modelled segment reaches past the sensor's end (:func:`beyond_sensor`:
  a ball cut by it, whose lines then give their one edge);
* optionally (``pixels``) the pixels of the spread edges' windows and of
  the end lines instead of their edges and areas (:func:`pixel_windows`).

A :class:`FitProblem` stacks the blocks' residuals (each block's: left
edges, right edges, areas, pixels) and Jacobian rows at fixed selections.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from ..compiled import as_arg
from ._fit_kernels import area_tables, fit_jacobian, fit_residuals, select_lines
from ..geometry.camera import LineScanCamera
from ..geometry.motion import PARAM_NAMES, BallMotion
from ..measure.robust import median as _median
from ..measure.edges import EdgeMeasurements
from ..model.blur import blur_diameter
from ..model.averaged import JacobianMemo, ModelEdges, ModelEvaluator, averaged_model, hybrid_jacobian, model_jacobian
from ..model.pixels import PixelWindows, pixel_residuals, pixel_residuals_jacobian
from .gains import GainColumns, GainElimination, gain_columns, interior_levels
from .settings import FitSettings
from .uncertainty import param_scale

__all__ = [
    "BIAS_NAME",
    "BlockState",
    "FitProblem",
    "LineDerivatives",
    "ResidualBlock",
    "Selection",
    "WeightTables",
    "beyond_sensor",
    "pixel_windows",
    "select_lines_of",
    "weight_tables",
    "whitened_jacobian",
]

BIAS_NAME = "edge_bias_px"  # the edge bias's name beside PARAM_NAMES
#: Fewest pixel residuals of a block whose correlation enters its covariance scale.
PIXEL_RUN_MIN = 32
_REL_STEP = 1e-3  # forward-difference step, fraction of param_scale


@dataclass(frozen=True)
class ResidualBlock:
    """One camera's measurements of the ball.

    Attributes
    ----------
    camera : LineScanCamera
    edges : EdgeMeasurements
        Its edges, areas and (optionally) pixel profiles.
    """

    camera: LineScanCamera
    edges: EdgeMeasurements


@dataclass(frozen=True)
class Selection:
    """Which residuals of one block enter the fit, their measurements and 1-sigma.

    Attributes
    ----------
    use_left, use_right, use_area : ndarray of bool (N,)
        Lines whose left edge, right edge, area gives a residual.
    sigma_left, sigma_right, sigma_area : ndarray
        1-sigma of those residuals (one per selected line, in line order), pixels.
    meas_left, meas_right, meas_area : ndarray
        Their measured values, pixels.
    pixels : PixelWindows or None
        The fitted pixels (after the edges and areas), or None.
    gains : GainColumns or None
        The pixels' column gains, eliminated nuisance parameters with a
        prior (:mod:`ballscan.solve.gains`): one prior row each after the
        pixels; None: gains known.
    n_left, n_right, n_area, n_pixels : int
        Residuals of each kind (derived).
    n_residuals : int
        All of them, the gains' prior rows included (derived).
    n_groups : int
        Free brightnesses of the pixels and column gains, nuisance parameters (derived).
    n_edge_lines : int
        Lines with both edges, as edges or as the pixels of their windows (derived).
    n_single_edge_lines : int
        Lines with one edge only (a ball cut by the sensor's end), derived.
    """

    use_left: np.ndarray
    use_right: np.ndarray
    use_area: np.ndarray
    sigma_left: np.ndarray
    sigma_right: np.ndarray
    sigma_area: np.ndarray
    meas_left: np.ndarray
    meas_right: np.ndarray
    meas_area: np.ndarray
    pixels: PixelWindows | None = None
    gains: GainColumns | None = None
    n_left: int = field(init=False)
    n_right: int = field(init=False)
    n_area: int = field(init=False)
    n_pixels: int = field(init=False)
    n_residuals: int = field(init=False)
    n_groups: int = field(init=False)
    n_edge_lines: int = field(init=False)
    n_single_edge_lines: int = field(init=False)

    def correlated_runs(self, r: np.ndarray) -> tuple[np.ndarray, ...]:
        """This block's whitened residuals ``r`` in the runs whose correlation the covariance scale measures.

        The left and the right edges (line order) and, where the block has
        at least :data:`PIXEL_RUN_MIN` of them, its pixels (window by
        window, line by line): a shaded or textured ball leaves model error
        correlated over neighbouring pixels as over neighbouring edges, and
        it widens the covariance alike
        (:func:`ballscan.solve.uncertainty.residual_scale`).
        """
        nl, nr = self.n_left, self.n_right
        edges = (r[:nl], r[nl : nl + nr])
        if self.n_pixels < PIXEL_RUN_MIN:
            return edges
        o = nl + nr + self.n_area
        return edges + (r[o : o + self.n_pixels],)

    @property
    def n_line_pairs(self) -> int:
        """Lines with both edges plus half those with one: the edge count in lines' worth."""
        return self.n_edge_lines + self.n_single_edge_lines // 2

    def __post_init__(self) -> None:
        # the counts, once (the fit reads them several times per round)
        px = self.pixels
        n_l, n_r, n_a = int(self.use_left.sum()), int(self.use_right.sum()), int(self.use_area.sum())
        n_p = 0 if px is None else px.n_pixels
        put = object.__setattr__
        put(self, "n_left", n_l)
        put(self, "n_right", n_r)
        put(self, "n_area", n_a)
        put(self, "n_pixels", n_p)
        n_g = 0 if self.gains is None else self.gains.n_columns
        put(self, "n_residuals", n_l + n_r + n_a + n_p + n_g)
        put(self, "n_groups", (0 if px is None else px.n_groups) + n_g)
        put(self, "n_edge_lines", int((self.use_left & self.use_right).sum()) + (0 if px is None else px.n_spread))
        put(self, "n_single_edge_lines", int((self.use_left ^ self.use_right).sum()))


@dataclass(frozen=True)
class WeightTables:
    """Per-line measurements and 1-sigma of every residual kind, computed once per fit (pixels).

    Attributes
    ----------
    has_wide : bool
        The edges carry wide-window edges (else the ``*_wide`` fields repeat the narrow ones).
    left, right, sigma_left, sigma_right : ndarray (N,)
        Narrow-window edges and their sigmas (floor and texture included).
    left_wide, right_wide, sigma_left_wide, sigma_right_wide : ndarray (N,)
        The same for the wide window.
    area, sigma_area : ndarray (N,)
        Summed coverage (optionally levelled by the local brightness) and its
        sigma with the relative ``area_rel_sigma``.
    area_levelled, sigma_area_levelled : ndarray (N,)
        Covered length (area over the shading model's level) and its sigma.
    levelled : ndarray of bool (N,)
        Lines that have a level.
    """

    has_wide: bool
    left: np.ndarray
    right: np.ndarray
    sigma_left: np.ndarray
    sigma_right: np.ndarray
    left_wide: np.ndarray
    right_wide: np.ndarray
    sigma_left_wide: np.ndarray
    sigma_right_wide: np.ndarray
    area: np.ndarray
    sigma_area: np.ndarray
    area_levelled: np.ndarray
    sigma_area_levelled: np.ndarray
    levelled: np.ndarray


def _nan_to_zero(a: np.ndarray) -> np.ndarray:
    """``a`` with NaN as 0 (``np.nan_to_num`` without its infinities' clipping, at a third of its cost)."""
    return np.where(np.isnan(a), 0.0, a)


def weight_tables(edges: EdgeMeasurements, settings: FitSettings) -> WeightTables:
    """The per-line measurements and 1-sigma of :class:`WeightTables`.

    Edge sigmas: the pixel noise, ``edge_floor_px`` (``matched_floor_px`` for
    matched edges) and ``texture_gain`` times the texture indicator in
    quadrature; area sigmas: the pixel noise, ``area_rel_sigma`` times the
    area and ``area_floor_px`` in quadrature (levelled areas:
    :func:`_area_tables`).
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
    sl_n = np.sqrt(_nan_to_zero(edges.left_sigma_px) ** 2 + floor2_l + tex_l)
    sr_n = np.sqrt(_nan_to_zero(edges.right_sigma_px) ** 2 + floor2_r + tex_r)
    if has_wide:
        el_w, er_w = edges.left_wide_px, edges.right_wide_px
        sl_w = np.sqrt(_nan_to_zero(edges.left_wide_sigma_px) ** 2 + floor2 + tex_l)
        sr_w = np.sqrt(_nan_to_zero(edges.right_wide_sigma_px) ** 2 + floor2 + tex_r)
    else:
        el_w, er_w, sl_w, sr_w = edges.left_px, edges.right_px, sl_n, sr_n
    ma = _area_levelled(edges, settings)
    sa = np.sqrt(edges.area_sigma_px**2 + (settings.area_rel_sigma * np.maximum(ma, 0.0)) ** 2 + settings.area_floor_px**2)
    ma_lev, sa_lev, levelled = _area_tables(edges, settings)
    return WeightTables(
        has_wide, edges.left_px, edges.right_px, sl_n, sr_n, el_w, er_w, sl_w, sr_w, ma, sa, ma_lev, sa_lev, levelled
    )


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



def select_lines_of(edges: EdgeMeasurements, me: ModelEdges, settings: FitSettings):
    """Which lines give edge residuals (narrow or wide window) and which give area residuals.

    Edges where the model ``me`` (one parameter set, arrays (N,)) sees the
    ball during the whole exposure, with its edge spread at most
    ``max_spread_px`` (the narrow window's edges) or up to
    ``max_spread_wide_px`` (the wide window's); area lines: no usable edge,
    and the line's area is not spoiled (``edges.end_line``), or no signal at
    all (lines around the ball), never ``edges.area_excluded``.  Returns
    ``(use_l, use_r, use_a, wide_l, wide_r)``; one compiled pass (:func:`ballscan.solve._fit_kernels.select_lines`).
    """
    wide = edges.left_wide_px is not None and settings.max_spread_wide_px > settings.max_spread_px
    e = edges
    masks = [as_arg(m, np.bool_) for m in (me.valid, e.left_ok, e.right_ok, e.end_line)]
    # (the narrow window's arrays stand in for the wide one's, unread, when it is not used)
    if wide:
        wl_ok, wr_ok, wl, wr = e.left_wide_ok, e.right_wide_ok, e.left_wide_px, e.right_wide_px
    else:
        wl_ok, wr_ok, wl, wr = e.left_ok, e.right_ok, e.left_px, e.right_px
    use_l, use_r, use_a, wide_l, wide_r = select_lines(
        as_arg(me.presence), masks[0], as_arg(me.spread_px), masks[1], masks[2], as_arg(e.left_px), as_arg(e.right_px), masks[3],
        wide, as_arg(wl_ok, np.bool_), as_arg(wr_ok, np.bool_), as_arg(wl), as_arg(wr),
        float(settings.max_spread_px), float(settings.max_spread_wide_px), bool(settings.end_line_areas),
    )
    if e.area_excluded is not None:
        use_a &= ~e.area_excluded
    return use_l, use_r, use_a, wide_l, wide_r


def beyond_sensor(me: ModelEdges, width_px: int, margin_px: float = 1.0) -> np.ndarray:
    """Lines whose modelled segment reaches past the sensor's first or last pixel (arrays (N,) of ``me``).

    Such a line's summed coverage shows only the part on the sensor (a ball
    cut by the sensor's end), so its area cannot enter the fit; ``margin_px``
    beyond half the edges' spread keeps the partly covered end pixel out too.
    """
    half = 0.5 * _nan_to_zero(me.spread_px) + margin_px
    with np.errstate(invalid="ignore"):
        return (me.presence > 0) & ((me.left_px - half < 0.0) | (me.right_px + half > width_px - 1.0))


def _weighted(T: WeightTables, use_l, use_r, use_a, wide_l, wide_r, loose_a, pixels, gains=None) -> Selection:
    """The selection of the masks with its measurements and 1-sigma from the tables.

    Edges in ``wide_l`` / ``wide_r`` come from the wide window; areas of
    lines in ``loose_a`` (None: none) are not levelled; ``gains`` the
    pixels' column gains (:class:`Selection`).
    """
    n = use_l.size
    wl = np.zeros(n, dtype=bool) if wide_l is None or not T.has_wide else wide_l
    wr = np.zeros(n, dtype=bool) if wide_r is None or not T.has_wide else wide_r
    lev = T.levelled if loose_a is None else T.levelled & ~loose_a
    return Selection(
        use_l,
        use_r,
        use_a,
        np.where(wl, T.sigma_left_wide, T.sigma_left)[use_l],
        np.where(wr, T.sigma_right_wide, T.sigma_right)[use_r],
        np.where(lev, T.sigma_area_levelled, T.sigma_area)[use_a],
        np.where(wl, T.left_wide, T.left)[use_l],
        np.where(wr, T.right_wide, T.right)[use_r],
        np.where(lev, T.area_levelled, T.area)[use_a],
        pixels,
        gains,
    )


def pixel_windows(
    edges: EdgeMeasurements, me: ModelEdges, end_p: np.ndarray, spread_p: np.ndarray, t_c: float, settings: FitSettings
) -> PixelWindows | None:
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
    return PixelWindows(
        t_s=edges.t_s[idx],
        cols_px=cols_k,
        mask=m,
        values=packed(prof[rows, ci], 0.0),  # finite (the mask)
        weights=packed(w, 0.0),
        shade=packed(shade, 1.0),
        group=packed(g_dense.astype(np.int64), np.int64(-1)),
        n_groups=int(g_dense.max()) + 1,
        n_pixels=int(rows.size),
        n_spread=int(spread_p[idx].sum()),
        nodes=settings.pixel_nodes,
    )



class LineDerivatives:
    """Per-line derivatives of a block's last Jacobian, for the next round's start (pixels per parameter unit).

    A plain record (slots: made once per Jacobian, in the solver's loop).

    Attributes
    ----------
    d_left, d_right, d_area : ndarray (N, 6)
    used : ndarray of bool (N,)
        Lines whose derivatives were computed (the others are unread).
    fd_rows : ndarray of bool (N,)
        Lines whose area derivative is the averaged model's.
    """

    __slots__ = ("d_left", "d_right", "d_area", "used", "fd_rows")

    def __init__(self, d_left: np.ndarray, d_right: np.ndarray, d_area: np.ndarray, used: np.ndarray, fd_rows: np.ndarray):
        self.d_left, self.d_right, self.d_area, self.used, self.fd_rows = d_left, d_right, d_area, used, fd_rows


class BlockState:
    """A block's working state during one fit: the model at the last point, the weights and the Jacobian's memory.

    Built once per fit (:func:`ballscan.solve.fit.fit_blocks`); the fit's
    rounds (outlier rejection, re-selection) and their problems share it.

    Attributes
    ----------
    block : ResidualBlock
    radius_m : float
        Ball radius (fixed), m.
    acceleration_mps2 : tuple of 3 floats
        Known acceleration (fixed), m/s^2.
    settings : FitSettings
    scale : ndarray (6,)
        :func:`ballscan.solve.uncertainty.param_scale` at the start.
    evaluate : ModelEvaluator
        The averaged model at the block's lines with ``settings.n_nodes``.
    tables : WeightTables
    rejected_left, rejected_right : ndarray of bool (N,)
        Edges rejected as outliers so far (left out of every later selection).
    model_key : bytes or None
        The parameters (bytes of the six) of the cached ``model``.
    model : ModelEdges or None
        The last model evaluation (one parameter set, arrays (1, N)), shared
        by the residual selection and the solver: a round's selection and
        its first residuals are taken at the same point.
    memo : JacobianMemo
        The finite-difference rows of :func:`ballscan.model.averaged.hybrid_jacobian`.
    line_derivatives : LineDerivatives or None
        The last Jacobian's per-line derivatives (None after a pixel fit).
    """

    def __init__(self, block: ResidualBlock, initial: BallMotion, settings: FitSettings):
        self.block = block
        self.radius_m = initial.radius_m
        self.acceleration_mps2 = initial.acceleration_mps2
        self.settings = settings
        self.scale = param_scale(block.camera, initial)
        self.evaluate = ModelEvaluator(block.camera, self.radius_m, block.edges.t_s, self.acceleration_mps2, settings.n_nodes)
        self.tables = weight_tables(block.edges, settings)
        n = block.edges.t_s.size
        self.rejected_left = np.zeros(n, dtype=bool)
        self.rejected_right = np.zeros(n, dtype=bool)
        self.model_key: bytes | None = None
        self.model: ModelEdges | None = None
        self.memo = JacobianMemo()
        self.line_derivatives: LineDerivatives | None = None

    def model_at(self, theta: np.ndarray) -> ModelEdges:
        """The averaged model (with edge spread and validity) at the six parameters ``theta[:6]``, arrays (1, N)."""
        th = np.asarray(theta, dtype=float)[:6]
        key = th.tobytes()
        if self.model is None or self.model_key != key:
            # always with the edge spread, so that the next round's selection
            # at the solution reuses the solver's last evaluation
            self.model = self.evaluate(th[None, :])
            self.model_key = key
        return self.model

    def select(self, theta: np.ndarray, level_partial: bool) -> Selection:
        """Residual selection and weights at ``theta``, less the rejected edges.

        ``level_partial``: the lines the ball enters or leaves during the
        exposure get their levelled areas (``area_level_partial`` or the
        trial of ``area_partial_check``), else their plain ones.
        """
        s, edges = self.settings, self.block.edges
        me = self.model_at(theta)
        me = ModelEdges(me.left_px[0], me.right_px[0], me.presence[0], me.area_px[0], me.spread_px[0], me.valid[0])
        ul, ur, ua, wl, wr = select_lines_of(edges, me, s)
        ul, ur = ul & ~self.rejected_left, ur & ~self.rejected_right
        ua = ua & ~beyond_sensor(me, self.block.camera.width)
        pix = gains = None
        if s.pixels and edges.profile is not None:
            # the ends seen during the whole exposure: their pixels instead of
            # their areas, and the spread edges' windows instead of the edges
            full = edges.signal & me.valid & ((me.presence >= 0.999) | s.pixel_partial)
            end_p = ua & full
            spread_p = full & ~end_p & (me.spread_px >= s.pixel_min_spread_px) & (ul | ur)
            pix = pixel_windows(edges, me, end_p, spread_p, float(theta[0]), s)
            if pix is not None:
                ua = ua & ~end_p
                ul, ur = ul & ~spread_p, ur & ~spread_p
                if s.pixel_gain_sigma > 0:
                    # the column gains' prior, with the interior pixels beyond the windows of the lines seen whole
                    whole = edges.signal & me.valid & (me.presence >= 0.999) & ~end_p
                    reach = 0.5 * _nan_to_zero(me.spread_px) + s.pixel_window_px
                    inner = interior_levels(edges, me.left_px, me.right_px, reach, whole, s.pixel_floor)
                    gains = gain_columns(pix, s.pixel_gain_sigma, inner)
        loose = None if (s.area_level_partial or level_partial) else me.presence < 0.999
        return _weighted(self.tables, ul, ur, ua, wl, wr, loose, pix, gains)


class _BlockTerms:
    """One block's selection in the compiled kernels' form, converted once per problem."""

    __slots__ = ("state", "sel", "il", "ir", "ia", "ml", "mr", "ma", "sl", "sr", "sa", "used", "n_pix", "gains_key", "gains")

    def __init__(self, state: BlockState, sel: Selection):
        self.state, self.sel = state, sel
        self.il, self.ir, self.ia = np.flatnonzero(sel.use_left), np.flatnonzero(sel.use_right), np.flatnonzero(sel.use_area)
        self.ml, self.mr, self.ma = as_arg(sel.meas_left), as_arg(sel.meas_right), as_arg(sel.meas_area)
        self.sl, self.sr, self.sa = as_arg(sel.sigma_left), as_arg(sel.sigma_right), as_arg(sel.sigma_area)
        self.used = sel.use_left | sel.use_right | sel.use_area
        self.n_pix = sel.n_pixels
        # the column gains eliminated at the last point (bytes of its six parameters)
        self.gains_key: bytes | None = None
        self.gains: GainElimination | None = None

    def eliminated(self, th: np.ndarray, raw_of: Callable[[], np.ndarray]) -> GainElimination:
        """The column gains eliminated at ``th`` (kept for the next call at the same ``th``); ``raw_of()`` gives its raw pixel residuals."""
        key = th.tobytes()
        if self.gains is None or self.gains_key != key:
            self.gains, self.gains_key = GainElimination(self.sel.gains, raw_of()), key
        return self.gains


_NO_PIXELS = np.zeros(0)
_NO_PIXEL_ROWS = np.zeros((0, 6))


class FitProblem:
    """The whitened residuals and Jacobian of one or more residual blocks at fixed selections.

    The parameters ``x`` are the six of :data:`PARAM_NAMES`, shared by the
    blocks, plus the edge bias ``b`` (pixels, shared) when ``fit_bias``.
    The residuals are the blocks' in order (each: left edges, right edges,
    areas, pixels); the Jacobian's rows stack the same way.

    Parameters
    ----------
    states : sequence of BlockState
    selections : sequence of Selection
        One per block.
    fit_bias : bool
        Whether ``x`` holds the edge bias (7 parameters).

    Attributes
    ----------
    terms : tuple
        Per block: its state and selection, with the selected lines' indices,
        measurements and sigmas converted once into the compiled kernels' form.
    fit_bias : bool
    settings : FitSettings
        The blocks' (shared) settings.
    last_key : bytes or None
        Bytes of the ``x`` of the last residuals.
    last_residuals : ndarray or None
        Those residuals (the Jacobian at an accepted point reuses them).
    """

    def __init__(self, states, selections, fit_bias: bool):
        self.terms = tuple(_BlockTerms(st, sel) for st, sel in zip(states, selections, strict=True))
        self.fit_bias = bool(fit_bias)
        self.settings = self.terms[0].state.settings
        self.last_key: bytes | None = None
        self.last_residuals: np.ndarray | None = None

    @property
    def selections(self) -> tuple[Selection, ...]:
        return tuple(t.sel for t in self.terms)

    @property
    def block_sizes(self) -> tuple[int, ...]:
        """Residuals of each block."""
        return tuple(t.sel.n_residuals for t in self.terms)

    def residuals(self, x: np.ndarray) -> np.ndarray:
        """Whitened residuals at ``x`` (the blocks' concatenated)."""
        th, b = x[:6], (x[6] if self.fit_bias else 0.0)
        if len(self.terms) == 1:
            r = self._block_residuals(self.terms[0], th, b)
        else:
            r = np.concatenate([self._block_residuals(t, th, b) for t in self.terms])
        self.last_key, self.last_residuals = x.tobytes(), r
        return r

    def _block_residuals(self, t: _BlockTerms, th: np.ndarray, b: float) -> np.ndarray:
        st = t.state
        me = st.model_at(th)
        if t.sel.pixels is None:
            tail = _NO_PIXELS
        elif t.sel.gains is None:
            tail = as_arg(self._pixel_res(st, t.sel.pixels, th[None])[0])
        else:
            tail = as_arg(t.eliminated(th, lambda: self._pixel_res(st, t.sel.pixels, th[None])[0]).residuals)
        return fit_residuals(
            me.left_px[0], me.right_px[0], me.area_px[0], t.il, t.ir, t.ia, float(b), t.ml, t.mr, t.ma, t.sl, t.sr, t.sa, tail
        )

    def jacobian(self, x: np.ndarray) -> np.ndarray:
        """Jacobian of :meth:`residuals` at ``x`` (rows stacked as the residuals, per parameter unit)."""
        return self.residuals_and_jacobian(x)[1]

    def residuals_and_jacobian(self, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Residuals and Jacobian at ``x`` (the residuals reused when they were the last computed)."""
        if self.settings.jacobian_reach > 0:
            r = self.last_residuals if self.last_key == x.tobytes() else self.residuals(x)
            if len(self.terms) == 1:
                return r, self._hybrid_rows(self.terms[0], x[:6], r)
            rows = []
            o = 0
            for t in self.terms:
                n = t.sel.n_residuals
                rows.append(self._hybrid_rows(t, x[:6], r[o : o + n]))
                o += n
        else:
            pairs = [self._fd_block(t, x) for t in self.terms]
            r = pairs[0][0] if len(pairs) == 1 else np.concatenate([p[0] for p in pairs])
            rows = [p[1] for p in pairs]
        return r, rows[0] if len(rows) == 1 else np.vstack(rows)

    def _hybrid_rows(self, t: _BlockTerms, th: np.ndarray, r: np.ndarray) -> np.ndarray:
        """One block's Jacobian rows: :func:`ballscan.model.averaged.hybrid_jacobian` and the pixels' (``r`` its residuals)."""
        st, s = t.state, self.settings
        base = None
        if s.jacobian_nodes == s.n_nodes:
            me0 = st.model_at(th)
            base = (me0.left_px[0], me0.right_px[0], me0.area_px[0])
        dl, dr, da = hybrid_jacobian(
            st.block.camera, th, st.radius_m, st.block.edges.t_s, st.scale, st.acceleration_mps2, fd_lines=t.sel.use_area,
            needed=t.used, reach_limit=s.jacobian_reach, rel_step=_REL_STEP, n_nodes=s.jacobian_nodes,
            memo=st.memo, reuse_px=s.jacobian_reuse_px, base=base, analytic=s.edge_jacobian == "analytic",
        )
        if t.sel.pixels is None:
            st.line_derivatives = LineDerivatives(dl, dr, da, t.used, t.sel.use_area | st.memo.last_fd)
            return self._assemble(t, dl, dr, da, _NO_PIXEL_ROWS)
        st.line_derivatives = None
        if t.sel.gains is None:
            # the base set's pixel residuals are the tail of r
            return self._assemble(t, dl, dr, da, self._pixel_jac(st, t.sel.pixels, th, r[r.size - t.n_pix :]))
        g = t.eliminated(th, lambda: self._pixel_res(st, t.sel.pixels, th[None])[0])
        return self._assemble(t, dl, dr, da, g.jacobian(self._pixel_jac(st, t.sel.pixels, th, g.raw)))

    def _fd_block(self, t: _BlockTerms, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """One block's residuals and rows by forward differences of the averaged model on every line (``jacobian_reach`` 0)."""
        st, s = t.state, self.settings
        th, b = x[:6], (x[6] if self.fit_bias else 0.0)
        cam, R, tl, acc = st.block.camera, st.radius_m, st.block.edges.t_s, st.acceleration_mps2
        me, dl, dr, da = model_jacobian(cam, th, R, tl, st.scale, acc, n_nodes=s.jacobian_nodes)
        if s.jacobian_nodes != s.n_nodes:
            me = averaged_model(cam, th[None], R, tl, acc, s.n_nodes)
            me = ModelEdges(me.left_px[0], me.right_px[0], me.presence[0], me.area_px[0], me.spread_px[0], me.valid[0])
        sel = t.sel
        pr0 = self._pixel_res(st, sel.pixels, th[None])[0]
        jp = self._pixel_jac(st, sel.pixels, th, pr0)
        if sel.gains is not None:
            g = t.eliminated(th, lambda: pr0)
            pr0, jp = g.residuals, g.jacobian(jp)
        r = np.concatenate([
            (me.left_px[sel.use_left] - b - t.ml) / t.sl, (me.right_px[sel.use_right] + b - t.mr) / t.sr,
            (me.area_px[sel.use_area] - t.ma) / t.sa, pr0,
        ])
        self._keep(t, dl, dr, da, t.used)
        return r, self._assemble(t, dl, dr, da, jp)

    def _keep(self, t: _BlockTerms, dl, dr, da, fd_rows) -> None:
        """Store the block's per-line derivatives for the next round's start (not after a pixel fit)."""
        t.state.line_derivatives = None if t.sel.pixels is not None else LineDerivatives(dl, dr, da, t.used, fd_rows)

    def _assemble(self, t: _BlockTerms, dl, dr, da, jp) -> np.ndarray:
        """Whitened Jacobian rows of the block's selection from per-line derivatives (one compiled pass)."""
        return fit_jacobian(as_arg(dl), as_arg(dr), as_arg(da), t.il, t.ir, t.ia, t.sl, t.sr, t.sa, as_arg(jp), self.fit_bias)

    def _pixel_res(self, st: BlockState, pix: PixelWindows | None, thetas: np.ndarray) -> np.ndarray:
        if pix is None:
            return np.zeros((thetas.shape[0], 0))
        return pixel_residuals(st.block.camera, thetas, st.radius_m, pix, st.acceleration_mps2, self.settings.n_nodes)

    def _pixel_jac(self, st: BlockState, pix: PixelWindows | None, th: np.ndarray, base_r: np.ndarray) -> np.ndarray:
        """The pixel residuals' Jacobian (M, 6) at ``th``, whose residuals are ``base_r``."""
        if pix is None:
            return _NO_PIXEL_ROWS
        s = self.settings
        # the forward-mode pixels know no lens blur: their differences where the camera has one
        if s.pixel_jacobian == "analytic" and not np.any(st.acceleration_mps2) and blur_diameter(st.block.camera) == 0:
            return pixel_residuals_jacobian(st.block.camera, th, st.radius_m, pix, s.n_nodes)
        h = _REL_STEP * st.scale
        return ((self._pixel_res(st, pix, th + np.diag(h)) - base_r) / h[:, None]).T

    def start(self) -> tuple[None, np.ndarray] | None:
        """``(None, J)`` from the blocks' last per-line derivatives when they cover this selection, else None.

        A later round (after rejecting edges) starts from the last
        Jacobian, taken at or next to its start; its residuals are
        recomputed by the solver.
        """
        rows = []
        for t in self.terms:
            c = t.state.line_derivatives
            if t.sel.pixels is not None or c is None:
                return None
            if np.any(t.used & ~c.used) or np.any(t.sel.use_area & ~c.fd_rows):
                return None
            rows.append(self._assemble(t, c.d_left, c.d_right, c.d_area, _NO_PIXEL_ROWS))
        return None, rows[0] if len(rows) == 1 else np.vstack(rows)


def whitened_jacobian(
    camera: LineScanCamera, edges: EdgeMeasurements, motion: BallMotion, settings: FitSettings = FitSettings()
) -> tuple[np.ndarray, tuple[str, ...]]:
    """Jacobian of the fit's whitened residuals at ``motion`` (Eq. (7)-(10)), per parameter unit.

    Same edge and area selection and weights as
    :func:`ballscan.solve.fit.fit_motion` with ``area_level_partial`` and
    without ``pixels`` (the pixel residuals are not included;
    :func:`ballscan.solve.precision.pixel_crlb` bounds those); one column
    per parameter of :data:`PARAM_NAMES` plus ``edge_bias_px`` when
    ``settings.fit_edge_bias``.  ``J^T J`` is the Fisher information of the
    edge measurements (Gaussian noise), used by :mod:`ballscan.solve.precision`.
    """
    theta = motion.to_params()
    scale = param_scale(camera, motion)
    me, dl, dr, da = model_jacobian(camera, theta, motion.radius_m, edges.t_s, scale, motion.acceleration_mps2, n_nodes=settings.n_nodes)
    use_l, use_r, use_a, wide_l, wide_r = select_lines_of(edges, me, settings)
    use_a = use_a & ~beyond_sensor(me, camera.width)
    sel = _weighted(weight_tables(edges, settings), use_l, use_r, use_a, wide_l, wide_r, None, None)
    sl, sr, sa = sel.sigma_left, sel.sigma_right, sel.sigma_area
    J = np.vstack([dl[use_l] / sl[:, None], dr[use_r] / sr[:, None], da[use_a] / sa[:, None]])
    names = PARAM_NAMES
    if settings.fit_edge_bias:
        jb = np.concatenate([-1.0 / sl, 1.0 / sr, np.zeros(int(use_a.sum()))])
        J = np.hstack([J, jb[:, None]])
        names = names + (BIAS_NAME,)
    return J, names
