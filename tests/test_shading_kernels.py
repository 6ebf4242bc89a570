"""The shading model's kernels (ballscan.measure._shading_kernels) against the numpy code of ballscan.measure.edges and ballscan.measure.shading."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

from ballscan.measure import edges as E
from ballscan.geometry.camera import LineScanCamera, line_times
from ballscan.measure.robust import median as _median
from ballscan.measure.detection import detect
from ballscan.errors import GeometryError
from ballscan.pipeline.background import full_background
from ballscan.measure.images import LineImage
from ballscan.geometry.motion import BallMotion
from ballscan.model.render import Appearance, SensorNoise, render
from ballscan.measure.shading import ball_limb, surface_normals
from ballscan.measure._shading_kernels import limb_values

MOTION = BallMotion(0.0335, 0.002, (0.0, 0.01, 3.0), (30.0, 0.0, 8.0))
LIMB_CAM = LineScanCamera(2048, 3000.0, 1023.5, 50000.0, None)
SPIN_MOTION = BallMotion(0.0335, 0.002, (0.0, 0.01, 3.0), (26.0, 2.0, 15.0))


# ------------------------------------------------------- numpy references
def _reference_limb_levels(limb, e, var0, L0, S, L_run, sl2, sw, n_win, win_first, win_last, lev, deep, pd, sd2, sgn, valid, lines_abs, m, tol, stats):
    """The numpy form of :func:`ballscan.measure.edges._limb_levels` (same arguments; ``stats["missing"]``: pixels the nearest-pixel fill was asked for)."""
    stats["missing"] = 0
    edge, var, L = e.copy(), var0.copy(), L0.copy()
    rows = np.flatnonzero(valid & np.isfinite(e))
    if rows.size == 0:
        return edge, var, L
    sg = sgn[rows].astype(float)
    lines_r = lines_abs[rows]
    e0 = e[rows]
    frac = (np.arange(m) + 0.5) / m
    # whole pixels (LimbProfile.pixel_coverage) times the surface's
    # brightness: the window from its outermost pixel inwards, then the
    # level run and the run inside it, in one array
    k = np.arange(int(n_win[rows].max()))
    first = np.where(sg > 0, np.minimum(win_first, win_last)[rows], np.maximum(win_first, win_last)[rows])
    px = np.concatenate([first[:, None] + sg[:, None] * k[None, :], lev[rows], deep[rows]], axis=1).astype(float)
    kw = k.size
    in_win = k[None, :] < n_win[rows][:, None]
    nlu = lev.shape[1]

    def profile(edge_at, point=None):
        """Model values and coverage of the rows' pixels with the mean edge at ``edge_at``, and ``point``.

        The surface's mean brightness where the ball covers each pixel:
        inside the limb the centre's at the line's centre time; on the partly
        covered pixels ``point``, the point model's, averaged over the
        exposure and the pixel's height (a shaded limb darkens steeply
        towards the edge and moves with it during the exposure), computed
        here when not given (it is the costly part; later placements move the
        edge by hundredths of a pixel); where neither is finite (a spread
        edge's tail, none of whose points is covered) the nearest pixel's.
        """
        off = sg[:, None] * (px - edge_at[:, None])
        cov = limb.pixel_coverage(lines_r, sg, off)
        partial = (cov > 0) & (cov < 1.0 - 1e-9)
        if point is None:
            point = np.full(cov.shape, np.nan)
            ri, ki = np.nonzero(partial)
            if ri.size:
                pts = px[ri, ki][:, None] - 0.5 + frac[None, :]
                v_pt, c_pt = limb(lines_r[ri], sg[ri], sg[ri, None] * (pts - edge_at[ri, None]))
                v_pt, c_pt = np.nan_to_num(v_pt).sum(axis=1), np.nan_to_num(c_pt).sum(axis=1)
                with np.errstate(invalid="ignore", divide="ignore"):
                    point[ri, ki] = np.where(c_pt > 0, v_pt / c_pt, np.nan)
        shade = np.where(partial & np.isfinite(point), point, limb.surface(lines_r, sg, off))
        missing = ~np.isfinite(shade) & (cov > 0)
        stats["missing"] += int(missing.sum())
        shade = _fill_nearest(shade, missing)
        return np.where(cov > 0, shade * cov, 0.0), cov, point

    # Two rounds: a level run in the tail of a spread edge's coverage is
    # more or less covered as the edge moves, so the ratio again at the new edge.
    er, point = e0, None
    for _ in range(2):
        at = er
        val, cov, point = profile(at, point)
        s_model = np.where(in_win, val[:, :kw], 0.0).sum(axis=1)
        # the model's covered length in the window, with its mean edge at `at`
        c_model = np.where(in_win, cov[:, :kw], 0.0).sum(axis=1)
        with np.errstate(invalid="ignore", divide="ignore"):
            ratio = s_model / c_model / val[:, kw : kw + nlu].mean(axis=1)
        usable = np.isfinite(ratio) & (c_model > 0.05) & (ratio >= 0.5) & (ratio <= 2.0)
        ratio = np.where(usable, ratio, 1.0)
        Lr = L_run[rows] * ratio
        covered = S[rows] / np.where(Lr > 0, Lr, 1.0)
        # The data's covered length S / L_eff against the model's: the mean
        # edge moves by their difference.  (``inner - S / L_eff`` alone is
        # the mean edge only when the window holds the whole ramp; a spread
        # edge's inner tail reaches past it, by 0.02-0.04 px of coverage
        # next to a ball's ends.)
        er = np.where(usable, at + sg * (c_model - covered), e0)
    # texture test with the model at the new edge: at the biased model-free
    # edge the model's runs sit a few tenths of a pixel off and a strongly
    # shaded limb would look like texture
    runs1 = profile(er, point)[0][:, kw:]
    with np.errstate(invalid="ignore", divide="ignore"):
        q_model = runs1[:, nlu:].mean(axis=1) / runs1[:, :nlu].mean(axis=1)
        q_data = pd[rows] / L_run[rows]
        q_sig = np.sqrt(sd2[rows] / L_run[rows] ** 2 + sl2[rows] * pd[rows] ** 2 / L_run[rows] ** 4)
        smooth = np.abs(q_data - q_model) <= 3.0 * q_sig + tol
    good = usable & smooth
    Ls = np.where(Lr > 0, Lr, 1.0)
    # L = ratio * L_run: the level run's noise enters scaled by the ratio
    v = (sw[rows] ** 2).sum(axis=1) / Ls**2 + (S[rows] / Ls**2) ** 2 * sl2[rows] * ratio**2
    edge[rows] = np.where(good, er, e0)
    var[rows] = np.where(good, v, var0[rows])
    L[rows] = np.where(good, Lr, L0[rows])
    return edge, var, L


def _fill_nearest(a: np.ndarray, missing: np.ndarray) -> np.ndarray:
    """``a`` (rows, K) with its ``missing`` entries replaced by the nearest finite, not missing entry of their row (left on ties).

    Entries of rows without any such value stay as they are.
    """
    if not missing.any():
        return a
    k = a.shape[1]
    col = np.arange(k)[None, :]
    have = np.isfinite(a) & ~missing
    left = np.maximum.accumulate(np.where(have, col, -1), axis=1)  # nearest on the left, -1 if none
    right = np.flip(np.minimum.accumulate(np.flip(np.where(have, col, k), axis=1), axis=1), axis=1)  # k if none
    pick = np.where((left >= 0) & ((right >= k) | (col - left <= right - col)), left, right)
    found = (pick >= 0) & (pick < k)
    filled = np.take_along_axis(a, np.clip(pick, 0, k - 1), axis=1)
    return np.where(missing & found, filled, a)


def test_fill_nearest_takes_the_closest_finite_value_of_the_row():
    a = np.array([[np.nan, 2.0, np.nan, np.nan, 5.0, np.nan], [np.nan, np.nan, np.nan, np.nan, np.nan, np.nan]])
    out = _fill_nearest(a, ~np.isfinite(a))
    assert out[0].tolist() == [2.0, 2.0, 2.0, 5.0, 5.0, 5.0]  # ties go left
    assert np.all(np.isnan(out[1]))  # nothing to take
    # only the entries asked for are filled
    keep = np.array([[True, False, False, False, False, False], [False] * 6])
    out = _fill_nearest(a, keep)
    assert out[0, 0] == 2.0 and np.isnan(out[0, 2])


# ---------------------------------------------------------------- fixtures
def _camera(k1: float = 0.0) -> LineScanCamera:
    return LineScanCamera(240, 3000.0, 119.5, 50000.0, None, k1=k1)


def _ball(k1: float = 0.0, texture: str = "tennis", seed: int = 4):
    """A shaded, textured, noisy ball on a 240-pixel sensor: its first-pass edges and limb model."""
    cam = _camera(k1)
    app = Appearance(ball_level=0.8, shading=True, light_dir=(-0.35, -0.45, -0.82), ambient=0.35, texture=texture, orientation_seed=1)
    noise = SensorNoise(bits=16, white_dn=1000.0, black_dn=0.0, read_dn=3.0, full_well_e=None, prnu_sigma=0.0)
    r = render(cam, (MOTION, app), 200, background_level=0.1, noise=noise, seed=seed)
    image = LineImage(r.image.astype(float), float(noise.max_dn), 16, "shaded ball")
    t = line_times(cam, image.data.shape[0])
    det = detect(image)
    bg = full_background(det)
    edges = E.measure_edges(image.data, det.regions[0], bg, det.noise_dn, t, saturation_dn=det.saturation_dn)
    limb = ball_limb(cam, MOTION, image.data, edges, t, bg)
    assert limb is not None
    return edges, limb


def _level_args(ps, valid=None, tol=0.002):
    return (
        ps.e, ps.var, ps.L, ps.S, ps.L_run, ps.sl2, ps.sw, ps.n_win, ps.win_first, ps.win_last, ps.lev, ps.deep, ps.pd, ps.sd2, ps.sgn,
        ps.limb_rows if valid is None else valid, ps.lines_abs, 3, tol,
    )


@pytest.fixture(scope="module")
def shaded_ball():
    return _ball()


# ------------------------------------------------------------ limb levels
def test_limb_levels_equal_the_numpy_form(shaded_ball):
    edges, limb = shaded_ball
    args = _level_args(edges._pass)
    stats = {}
    ref = _reference_limb_levels(limb, *args, stats)
    got = E._limb_levels(limb, *args)
    for a, b in zip(got, ref):
        assert np.array_equal(a, b, equal_nan=True)  # the same arithmetic in the same order
    rows = edges._pass.limb_rows
    assert np.mean(got[0][rows] != args[0][rows]) > 0.5  # most edges corrected
    assert stats["missing"] > 0  # the nearest-pixel fill ran


def test_limb_levels_without_a_model_edge_or_coverage_keep_the_model_free_edge(shaded_ball):
    edges, limb = shaded_ball
    ps = edges._pass
    rows = np.flatnonzero(ps.limb_rows & np.isfinite(ps.e))
    # a line without a model edge (NaN: the model does not see the ball there)
    gone = ps.lines_abs[rows[len(rows) // 3]]
    left = limb.left_px.copy()
    left[gone] = np.nan
    no_edge = replace(limb, left_px=left)
    # and a NaN chord sample (the coverage undefined) on another row
    sg = ps.sgn[rows].astype(float)
    lo, _, _ = no_edge._chords(ps.lines_abs[rows], sg, 4)
    lo[len(rows) // 2, 1, 0] = np.nan
    args = _level_args(ps)
    got = E._limb_levels(no_edge, *args)
    ref = _reference_limb_levels(no_edge, *args, {})
    for a, b in zip(got, ref):
        assert np.array_equal(a, b, equal_nan=True)
    hit = (ps.lines_abs == gone) & (ps.sgn > 0) & ps.limb_rows
    hit[rows[len(rows) // 2]] = True
    for a, a0 in zip(got, (ps.e, ps.var, ps.L)):
        assert np.array_equal(a[hit], a0[hit])


def test_limb_levels_without_rows(shaded_ball):
    edges, limb = shaded_ball
    args = _level_args(edges._pass, valid=np.zeros_like(edges._pass.limb_rows))
    got = E._limb_levels(limb, *args)
    for a, a0 in zip(got, (args[0], args[1], args[2])):
        assert np.array_equal(a, a0, equal_nan=True) and a is not a0


def test_limb_levels_through_a_distorted_lens():
    edges, limb = _ball(k1=-0.4)
    args = _level_args(edges._pass)
    got = E._limb_levels(limb, *args)
    ref = _reference_limb_levels(limb, *args, {})
    # each ray's Newton iteration stops on its own (numpy's when all have): 1e-12 px
    for a, b in zip(got, ref):
        assert np.array_equal(np.isnan(a), np.isnan(b))
        assert np.nanmax(np.abs(a - b) / np.maximum(np.abs(b), 1.0)) < 1e-9


# ----------------------------------------------------------- shading fit
def _reference_shading_fit(y, n, huber_k, n_iterations, diverged, flat_tol):
    """The numpy form of :func:`ballscan.measure._shading_kernels.shading_fit` (the rounds of :func:`ballscan.measure.shading.fit_shading`)."""
    X = np.column_stack([np.ones(y.size), n])
    X_dark = np.zeros((1, 4))
    X_dark[0, 0] = 1.0
    w = np.ones(y.size)
    active = np.ones(y.size, dtype=bool)
    coef = np.zeros(4)
    scale = 1.0
    best = (np.inf, coef)
    for _ in range(n_iterations):
        # the law is linear in (A, b) on the lit pixels; shadowed ones see A only
        Xa = np.where(active[:, None], X, X_dark)
        sw = np.sqrt(w)
        coef = np.linalg.lstsq(Xa * sw[:, None], y * sw, rcond=None)[0]
        lit = n @ coef[1:]
        active = lit > 0
        scale, w = _huber_round(y - coef[0] - np.maximum(lit, 0.0), huber_k)
        if scale < best[0]:
            best = (scale, coef)
    if scale > diverged * best[0]:
        # The lit / shadowed split makes the rounds a fixed-point iteration,
        # not a descent: on a flat ball a round that calls half of it
        # shadowed can run away to a strong light (seen: 152 DN of light and
        # a robust scale of 40 DN where the flat law leaves 5 DN; its end
        # levels then moved a ball's V.x by 21 sigma).  Keep the best round.
        scale, coef = best
    # A light that lights hardly any of the pixels (behind the ball: seen on
    # flat 8-bit renders, 19-117 DN of light on a 138 DN contrast at the
    # same robust scale as no light) is not measured: the flat law, unless
    # the light lowers the robust scale by more than flat_tol.
    amb, flat_scale = _flat_level(y, huber_k, n_iterations)
    if flat_scale <= (1.0 + flat_tol) * scale:
        coef, scale = np.array([amb, 0.0, 0.0, 0.0]), flat_scale
    return coef, scale


def _flat_level(y: np.ndarray, huber_k: float, n_iterations: int) -> tuple[float, float]:
    """Huber mean of ``y`` (reweighted as in :func:`fit_shading`) and the robust scale about it."""
    w = np.ones(y.size)
    level, scale = float(np.mean(y)), 1.0
    for _ in range(n_iterations):
        level = float(np.sum(w * y) / np.sum(w))
        scale, w = _huber_round(y - level, huber_k)
    return level, scale


def _huber_round(r: np.ndarray, huber_k: float) -> tuple[float, np.ndarray]:
    """The robust scale (MAD) of residuals ``r`` and their Huber weights at ``huber_k`` of it (one reweighting round)."""
    scale = max(1.4826 * float(_median(np.abs(r - _median(r)))), 1e-9)
    a = np.abs(r) / (huber_k * scale)
    return scale, np.where(a <= 1.0, 1.0, 1.0 / np.maximum(a, 1e-12))


def _interior(texture: str, light: bool = True, seed: int = 2):
    """The interior pixels and normals fit_shading fits on a rendered ball (noisy, textured or not, lit or flat)."""
    from ballscan.measure import shading as shading

    cam = _camera()
    app = Appearance(ball_level=0.7, shading=light, light_dir=(-0.35, -0.45, -0.82), ambient=0.35, texture=texture, orientation_seed=1)
    r = render(cam, (MOTION, app), 200, background_level=0.1, noise=None)
    data = 1000.0 * r.clean + 3.0 * np.random.default_rng(seed).standard_normal(r.clean.shape)
    image = LineImage(data, 1e9, 16, "ball")
    t = line_times(cam, 200)
    det = detect(image)
    edges = E.measure_edges(image.data, det.regions[0], full_background(det), det.noise_dn, t)
    got = {}
    orig = shading.shading_fit

    def grab(y, normals, *args):
        got["y"], got["n"] = y.copy(), normals.copy()
        return orig(y, normals, *args)

    shading.shading_fit = grab
    try:
        ball_limb(cam, MOTION, image.data, edges, t, full_background(det))
    finally:
        shading.shading_fit = orig
    return got["y"], got["n"]


@pytest.mark.parametrize("texture, light", [("none", True), ("tennis", True), ("none", False)])
def test_shading_fit_equals_the_numpy_rounds(texture, light):
    from ballscan.measure._shading_kernels import shading_fit

    y, n = _interior(texture, light)
    assert y.size >= 500
    for args in ((1.5, 4, 1.5, 0.01), (1.5, 4, np.inf, -1.0), (1.2, 7, 1.5, 0.01), (1.5, 0, 1.5, 0.01), (1.5, 1, 1.5, 0.01)):
        coef, scale = shading_fit(y, n, *args)
        ref_coef, ref_scale = _reference_shading_fit(y, n, *args)
        # the same LAPACK, BLAS and summation order: the same bits
        assert np.array_equal(coef, ref_coef) and scale == ref_scale, args
    # the lit ball keeps its light, the flat one the flat law
    coef, _ = shading_fit(y, n, 1.5, 4, 1.5, 0.01)
    assert (np.linalg.norm(coef[1:]) > 0) == light


def test_shading_fit_on_few_and_odd_pixels():
    from ballscan.measure._shading_kernels import shading_fit

    rng = np.random.default_rng(5)
    for size in (50, 51, 8, 7):
        n = rng.standard_normal((size, 3))
        n = n / np.linalg.norm(n, axis=1)[:, None]
        y = 100.0 + np.maximum(n @ np.array([10.0, -20.0, 5.0]), 0.0) + rng.standard_normal(size)
        y[::9] = 300.0  # outliers: the Huber weights
        coef, scale = shading_fit(y, n, 1.5, 4, 1.5, 0.01)
        ref_coef, ref_scale = _reference_shading_fit(y, n, 1.5, 4, 1.5, 0.01)
        assert np.array_equal(coef, ref_coef) and scale == ref_scale, size


# ------------------------------------------------- line levels and scatter
def _reference_line_levels(self, lines: np.ndarray, samples_per_px: int = 2) -> tuple[np.ndarray, np.ndarray]:
    """The numpy form of :meth:`ballscan.measure.shading.LimbProfile.line_levels` (``self`` the profile)."""
    lines = np.asarray(lines, dtype=int)
    if lines.size == 0:
        return np.zeros(0), np.zeros(0)
    left, right, spread = self.left_px[lines], self.right_px[lines], self.spread_px[lines]
    pad = np.nan_to_num(spread) / 2.0 + 1.5
    span = np.nan_to_num(right - left) + 2.0 * pad
    m = max(int(samples_per_px), 1)
    n_pos = int(np.ceil(np.max(span) * m)) if np.all(np.isfinite(span)) else 1
    offsets = -pad[:, None] + (np.arange(max(n_pos, 1)) + 0.5)[None, :] / m
    inside = offsets <= (span - pad)[:, None]
    val, cov = self(lines, np.ones(lines.size), offsets)
    with np.errstate(invalid="ignore", divide="ignore"):
        covered = np.where(inside, cov, 0.0).sum(axis=1)
        level = np.where(inside, val, 0.0).sum(axis=1) / covered
        level = np.where((covered > 0) & np.isfinite(left) & np.isfinite(right), level, np.nan)
        rel = self.level_rel_sigma * np.sqrt(self.level_ref_px / np.maximum(covered / m, 1.0))
    return level, np.where(np.isfinite(level), rel, np.nan)


def _reference_line_level_scatter(
    limb, edges, lines_ok: np.ndarray, spread_px: np.ndarray, left_px: np.ndarray, right_px: np.ndarray, max_lines: int = 40
) -> tuple[float, float]:
    """The numpy form of :func:`ballscan.measure.shading._line_level_scatter` (its arguments)."""
    if edges.profile is None or edges.profile_sigma is None:
        return math.nan, 1.0
    idx = np.flatnonzero(lines_ok)
    if idx.size > max_lines:
        idx = idx[np.linspace(0, idx.size - 1, max_lines).astype(int)]
    inset = 1.5 + np.nan_to_num(spread_px[idx])
    c0 = edges.profile_col0
    lo = np.ceil(left_px[idx] + inset).astype(int) - c0
    hi = np.floor(right_px[idx] - inset).astype(int) - c0
    lo, hi = np.clip(lo, 0, edges.profile.shape[1]), np.clip(hi, -1, edges.profile.shape[1] - 1)
    count = hi - lo + 1
    keep = count >= 3
    if keep.sum() < 3:
        return math.nan, 1.0
    idx, lo, count = idx[keep], lo[keep], count[keep]
    k = np.arange(count.max())[None, :]
    inside = k < count[:, None]
    cols = np.where(inside, lo[:, None] + k, lo[:, None])
    p = edges.profile[idx[:, None], cols]
    sp = edges.profile_sigma[idx[:, None], cols]
    lines_img = edges.lines[idx]
    model, hit = limb(lines_img, np.ones(idx.size), cols + c0 - limb.left_px[lines_img][:, None], average=False)
    # only where the model's surface is seen too (the model sits at a rough
    # motion: a pixel inside the measured ball may lie outside its silhouette)
    inside &= np.isfinite(p) & (np.nan_to_num(hit) > 0)
    n = inside.sum(axis=1)
    good = n >= 3
    with np.errstate(invalid="ignore", divide="ignore"):
        p_mean = np.where(inside, p, 0.0).sum(axis=1) / n
        m_mean = np.where(inside, model, 0.0).sum(axis=1) / n
        noise2 = np.where(inside, sp**2, 0.0).sum(axis=1) / n**2
        d = p_mean / m_mean - 1.0
        v = noise2 / m_mean**2
    good &= np.isfinite(d) & np.isfinite(v) & (m_mean > 0.05)
    if good.sum() < 3:
        return math.nan, 1.0
    return float(np.sqrt(max(float(np.mean(d[good] ** 2) - np.mean(v[good])), 0.0))), float(np.mean(n[good]))


def test_line_levels_equal_the_numpy_form(shaded_ball):
    edges, limb = shaded_ball
    lines = edges.lines[edges.signal]
    for ls in (lines, lines[:1], lines[:0], np.concatenate([lines[:3], [0]])):  # [0]: a line the model does not see
        for m in (2, 3, 1):
            got = limb.line_levels(ls, m)
            ref = _reference_line_levels(limb, ls, m)
            for a, b in zip(got, ref):
                assert np.array_equal(a, b, equal_nan=True)
    # the ends' levels differ from the middle's (the cap is lit or shaded unlike it)
    lev = limb.line_levels(lines)[0]
    assert np.nanmax(lev) - np.nanmin(lev) > 0.05
    # a spread-less model (every line sharp: one sample per position)
    sharp = replace(limb, sharp_px=np.inf)
    for a, b in zip(sharp.line_levels(lines), _reference_line_levels(sharp, lines)):
        assert np.array_equal(a, b, equal_nan=True)


def test_line_level_scatter_equals_the_numpy_form(shaded_ball):
    from ballscan.model.averaged import averaged_model
    from ballscan.measure.shading import _line_level_scatter

    edges, limb = shaded_ball
    me = averaged_model(limb.camera, MOTION.to_params()[None], MOTION.radius_m, edges.t_s, MOTION.acceleration_mps2)
    full = edges.left_ok & edges.right_ok & (me.presence[0] > 0.999)
    inner = (np.fmax(me.left_px[0], edges.left_px), np.fmin(me.right_px[0], edges.right_px))
    # saturated (NaN) pixels, a line without a model edge, few lines
    prof = edges.profile.copy()
    prof[edges.profile.shape[0] // 2, ::3] = np.nan
    left = limb.left_px.copy()
    left[edges.lines[np.flatnonzero(full)[5]]] = np.nan
    cases = [(edges, limb, full), (replace(edges, profile=prof), replace(limb, left_px=left), full)]
    few = np.zeros_like(full)
    few[np.flatnonzero(full)[:3]] = True
    cases += [(edges, limb, few), (edges, limb, np.zeros_like(full))]
    for e, lp, ok in cases:
        for max_lines in (40, 7, 1000):
            got = _line_level_scatter(lp, e, ok, me.spread_px[0], *inner, max_lines=max_lines)
            ref = _reference_line_level_scatter(lp, e, ok, me.spread_px[0], *inner, max_lines=max_lines)
            assert got == ref or (np.isnan(got[0]) and np.isnan(ref[0]) and got[1] == ref[1]), (got, ref)
    assert np.isfinite(_line_level_scatter(limb, edges, full, me.spread_px[0], *inner)[0])


# ------------------------------------------------------- interior normals
@pytest.mark.parametrize("k1", [0.0, -0.4])
def test_interior_normals_equal_the_surface_normals_and_the_usable_box(k1):
    from ballscan.measure._shading_kernels import interior_normals
    from ballscan.measure.shading import surface_normals

    cam = _camera(k1)
    rng = np.random.default_rng(7)
    lines = rng.integers(0, 200, 3000)
    t = line_times(cam, 200)[lines]
    cols = rng.integers(0, 240, 3000)
    usable = rng.random((150, 120)) > 0.2
    origin = (30, 60)
    m = MOTION
    law = (cam.focal_px, cam.principal_px, cam.k1, cam.k2, np.array(m.position_m), np.array(m.velocity_mps), np.zeros(3), m.t_c_s, m.radius_m)
    ref_hit, ref_n = surface_normals(cam, m, t, cols)
    r_box, c_box = lines - origin[0], cols - origin[1]
    inside = (r_box >= 0) & (r_box < usable.shape[0]) & (c_box >= 0) & (c_box < usable.shape[1])
    in_box = inside & usable[np.clip(r_box, 0, usable.shape[0] - 1), np.clip(c_box, 0, usable.shape[1] - 1)]
    for box, want in ((np.zeros((0, 0), dtype=bool), ref_hit), (usable, ref_hit & in_box)):
        hit, n, ok = interior_normals(t, cols, lines, box, *origin, *law)
        assert ok and np.array_equal(hit, want) and 100 < hit.sum() < hit.size
        if k1 == 0.0:
            assert np.array_equal(n[hit], ref_n[hit])
        else:
            # each ray's Newton iteration stops on its own
            assert np.abs(n[hit] - ref_n[hit]).max() < 1e-9


def test_limb_values_equal_the_surface_normals_and_the_shading_law():
    rng = np.random.default_rng(4)
    n_rows, width = 6, 9
    t_rows = 0.002 + np.linspace(-8e-4, 8e-4, n_rows)
    u = 1020.0 + rng.uniform(-40.0, 40.0, (n_rows, width))
    bg = 100.0 + rng.standard_normal((n_rows, width))
    sharp = np.array([True, False] * (n_rows // 2))
    tk = (np.arange(4) + 0.5) / 4 * LIMB_CAM.exposure - LIMB_CAM.exposure / 2
    hk = (np.arange(3) + 0.5) / 3 - 0.5
    light = np.array([-60.0, 80.0, -200.0])
    ambient, scale = 40.0, 700.0
    val, cov = limb_values(
        t_rows, LIMB_CAM.backproject(u), bg, sharp, tk, hk, LIMB_CAM.focal_px, np.array(SPIN_MOTION.position_m), np.array(SPIN_MOTION.velocity_mps),
        np.zeros(3), SPIN_MOTION.t_c_s, SPIN_MOTION.radius_m, light, ambient, scale,
    )
    for r in range(n_rows):
        ts, hs = (np.zeros(1), np.zeros(1)) if sharp[r] else (tk, hk)
        hit, n = surface_normals(LIMB_CAM, SPIN_MOTION, t_rows[r] + ts[:, None, None], u[r][None, None, :], hs[None, :, None])
        v = np.where(hit, (np.maximum(n @ light, 0.0) + ambient - bg[r]) / scale, 0.0)
        assert np.abs(val[r] - v.mean(axis=(0, 1))).max() < 1e-12
        assert np.array_equal(cov[r], hit.mean(axis=(0, 1)))
    assert 0.0 < cov.mean() < 1.0  # rays on and off the ball


def test_chord_rows_equals_the_numpy_form():
    from ballscan.measure._shading_kernels import chord_rows

    rng = np.random.default_rng(4)
    u_lo, u_hi, wgt = (rng.normal(size=(6, 3, 4)) for _ in range(3))
    left, right = rng.normal(size=6), rng.normal(size=6)
    inv = rng.integers(0, 6, 15)
    sg = rng.choice([1.0, -1.0, np.nan], 15)
    lo, hi, w = chord_rows(*(a.reshape(6, 12) for a in (u_lo, u_hi, wgt)), left, right, inv, sg)
    s3, le, ri = sg[:, None, None], left[inv][:, None, None], right[inv][:, None, None]
    assert np.array_equal(lo.reshape(15, 3, 4), np.where(s3 > 0, u_lo[inv] - le, ri - u_hi[inv]))
    assert np.array_equal(hi.reshape(15, 3, 4), np.where(s3 > 0, u_hi[inv] - le, ri - u_lo[inv]))
    assert np.array_equal(w.reshape(15, 3, 4), wgt[inv])


def test_level_spans_equals_the_numpy_form():
    from ballscan.measure._shading_kernels import level_spans

    rng = np.random.default_rng(5)
    left, right, spread = rng.normal(100.0, 5.0, 30), rng.normal(140.0, 5.0, 30), rng.uniform(0.0, 2.0, 30)
    left[3] = right[4] = spread[5] = np.nan
    for m in (1, 2, 3):
        pad = np.nan_to_num(spread) / 2.0 + 1.5
        span = np.nan_to_num(right - left) + 2.0 * pad
        got = level_spans(left, right, spread, m)
        assert np.array_equal(got[0], pad) and np.array_equal(got[1], span) and got[2] == np.max(span) * m
    # an infinite spread as np.nan_to_num takes it; an infinite span: no maximum
    spread[6] = np.inf
    pad = np.nan_to_num(spread) / 2.0 + 1.5
    span = np.nan_to_num(right - left) + 2.0 * pad
    got = level_spans(left, right, spread, 2)
    with np.errstate(over="ignore"):
        assert np.array_equal(got[0], pad) and np.array_equal(got[1], span) and got[2] == np.max(span) * 2
    right[6] = np.inf
    assert np.isnan(level_spans(left, right, spread, 2)[2])
