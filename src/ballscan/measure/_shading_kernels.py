"""Compiled loops of the shading model: the limb's values and levels, the shading law's fit, the line levels and their scatter.

The second edge pass (:func:`ballscan.measure.edges._limb_levels`)
evaluates the shading model on the ten pixels of each of some three hundred
edge windows, three times; the ends' line levels and their scatter
(:mod:`ballscan.measure.shading`) evaluate it on some forty lines each; the
shading law is a reweighted least-squares fit of some 800 interior pixels.
As numpy expressions each is some hundred operations on arrays of a few
thousand entries; the rows are independent, and one loop over them does the
same arithmetic in the same order: numpy's pairwise sums
(:func:`ballscan.compiled.pairwise_sum`) and the same LAPACK (gelsd) and
BLAS (gemv) calls, so the values are numpy's bits.  Under numpy's error
model a division by zero gives inf or NaN, which the rules reject.
"""

from __future__ import annotations

import math

import numpy as np

from ..compiled import jit, pairwise_sum
from ..geometry.lens import normalised
from ..model.coverage import grid_coverage, ramp_histogram


@jit(inline="always")
def _centres(t_row: float, sharp: bool, tk: np.ndarray, pos: np.ndarray, vel: np.ndarray, acc: np.ndarray, has_acc: bool, t_c: float, out: np.ndarray) -> int:
    """The sphere's centre ``(cx, cy, cz, |c|^2)`` (m, m^2) at each instant a row of line time ``t_row`` samples (see :func:`limb_values`), into ``out`` (n, 4); returns ``n``."""
    nt = 1 if sharp else tk.shape[0]
    for i in range(nt):
        dt = (t_row + (0.0 if sharp else tk[i])) - t_c
        cx = pos[0] + vel[0] * dt
        cy = pos[1] + vel[1] * dt
        cz = pos[2] + vel[2] * dt
        if has_acc:
            cx = cx + 0.5 * acc[0] * dt * dt
            cy = cy + 0.5 * acc[1] * dt * dt
            cz = cz + 0.5 * acc[2] * dt * dt
        out[i, 0] = cx
        out[i, 1] = cy
        out[i, 2] = cz
        out[i, 3] = cx * cx + cy * cy + cz * cz
    return nt


@jit(inline="always")
def _ray_normal(h: float, nu: float, cx: float, cy: float, cz: float, c2: float, R2: float):
    """Whether the ray from the camera along ``(h, nu, 1)`` meets the sphere of centre ``(cx, cy, cz)`` (m; ``c2 = |c|^2``, ``R2`` the radius squared, m^2), and the outward unit normal where it first does (zeros where it misses)."""
    inv = 1.0 / math.sqrt(h * h + nu * nu + 1.0)
    dx = h * inv
    dy = nu * inv
    dz = inv
    dc = dx * cx + dy * cy + dz * cz
    b = dc * dc - c2 + R2
    if b >= 0.0:
        s = dc - math.sqrt(b)
        nx = s * dx - cx
        ny = s * dy - cy
        nz = s * dz - cz
        a = 1.0 / max(math.sqrt(nx * nx + ny * ny + nz * nz), 1e-12)
        return True, nx * a, ny * a, nz * a
    return False, 0.0, 0.0, 0.0


@jit(inline="always")
def _limb_rays(nu: float, bg: float, cen: np.ndarray, nt: int, hs: np.ndarray, nh: int, R2: float, light: np.ndarray, ambient: float, scale: float):
    """One sensor position's mean normalised brightness and coverage over its samples (see :func:`limb_values`).

    ``nu`` the position's normalised coordinate, ``bg`` the background
    under it (DN), ``cen`` the centres of :func:`_centres` (``nt`` of
    them), ``hs`` the ``nh`` heights across the line over the focal length,
    ``R2`` the radius squared (m^2).
    """
    n_samples = float(nt * nh)
    s_val = 0.0
    s_hit = 0.0
    for i in range(nt):
        cx = cen[i, 0]
        cy = cen[i, 1]
        cz = cen[i, 2]
        c2 = cen[i, 3]
        for j in range(nh):
            hit, nx, ny, nz = _ray_normal(hs[j], nu, cx, cy, cz, c2, R2)
            if hit:
                lam = nx * light[0] + ny * light[1] + nz * light[2]
                s_val += (max(lam, 0.0) + ambient - bg) / scale
                s_hit += 1.0
    return s_val / n_samples, s_hit / n_samples


@jit(inline="always")
def _heights(sharp: bool, hk: np.ndarray, focal_px: float, out: np.ndarray) -> int:
    """The heights across the line a row samples over the focal length (one, 0, when sharp), into ``out``; returns their number."""
    nh = 1 if sharp else hk.shape[0]
    for j in range(nh):
        out[j] = (0.0 if sharp else hk[j]) / focal_px
    return nh


@jit()
def limb_values(
    t_rows: np.ndarray,
    n_u: np.ndarray,
    bg: np.ndarray,
    sharp: np.ndarray,
    tk: np.ndarray,
    hk: np.ndarray,
    focal_px: float,
    pos: np.ndarray,
    vel: np.ndarray,
    acc: np.ndarray,
    t_c: float,
    radius_m: float,
    light: np.ndarray,
    ambient: float,
    scale: float,
):
    """The shading law's normalised brightness and the ball's coverage at sensor positions (:meth:`ballscan.measure.shading.LimbProfile.__call__`).

    Row ``r`` (an edge of line time ``t_rows[r]``) has positions of
    normalised coordinate ``n_u[r]`` over the background ``bg[r]`` (DN); a
    ``sharp`` row takes one sample at the line's centre time and in the
    viewing plane, the others the mean over the exposure's instants ``tk``
    (s, from the centre time) and the heights ``hk`` (pixels) across the
    line.  Each sample's ray meets the sphere (centre ``pos + vel dt + acc
    dt^2 / 2``, ``dt = t - t_c``) or not; where it does, its value is
    ``(max(n . light, 0) + ambient - bg) / scale`` (``scale`` = polarity x
    contrast, DN), else 0.  Returns ``(value, coverage)`` (R, K): means
    over the samples.
    """
    R2 = radius_m * radius_m
    n_rows, K = n_u.shape
    val = np.empty((n_rows, K))
    cov = np.empty((n_rows, K))
    has_acc = acc[0] != 0.0 or acc[1] != 0.0 or acc[2] != 0.0
    cen = np.empty((max(tk.shape[0], 1), 4))
    hs = np.empty(max(hk.shape[0], 1))
    for r in range(n_rows):
        nt = _centres(t_rows[r], sharp[r], tk, pos, vel, acc, has_acc, t_c, cen)
        nh = _heights(sharp[r], hk, focal_px, hs)
        for k in range(K):
            val[r, k], cov[r, k] = _limb_rays(n_u[r, k], bg[r, k], cen, nt, hs, nh, R2, light, ambient, scale)
    return val, cov


@jit(inline="always")
def _limb_point(o, sg, edge_m, bg_row, width, cen, nt, hs, nh, focal, principal, k1, k2, R2, light, ambient, scale):
    """The model's normalised value and coverage at offset ``o`` (pixels inwards) from a row's mean edge ``edge_m``, and whether its ray converged (:func:`_limb_rays`)."""
    u = edge_m + sg * o
    # the background's column: clamped, then rounded (as LimbProfile.__call__)
    col = int(np.rint(min(max(u, 0.0), width - 1.0)))
    nu, ok = normalised(u, focal, principal, k1, k2)
    v, c = _limb_rays(nu, bg_row[col], cen, nt, hs, nh, R2, light, ambient, scale)
    return v, c, ok


@jit(inline="always", error_model="numpy")
def _limb_row_profile(
    r, at, sg, px, c_lo, c_hi, c_w, span, hwb, frac, want_point, point, wk, n_use, run_lo, run_hi,
    edge_m, bg_row, width, cen_pt, nt_pt, hs_pt, nh_pt, cen_c, hs_c, law, light,
):
    """Row ``r``'s model values and coverage of its pixels with the mean edge at ``at`` (the ``profile`` of :func:`ballscan.measure.edges._limb_levels`).

    Into ``wk`` (4, K): the pixels' offsets inwards from ``at``, coverage,
    brightness and values (coverage times brightness), the values only of
    the pixels asked for (the first ``n_use`` and ``run_lo`` to
    ``run_hi``).  The coverage is each whole pixel's by the chord samples
    (the unit grid of :func:`coverage_grid`, ``hwb`` its two buffers); the
    partly covered pixels take the point samples' brightness ``point[r]``
    (computed here when ``want_point``: ``frac`` positions across the
    pixel, each averaged over the exposure and the pixel's height:
    ``cen_pt, hs_pt``, see :func:`_limb_rays`), the others the surface's
    (``cen_c, hs_c``: at the line's centre time, in the viewing plane) at
    the pixel's centre (at least a quarter pixel inside), and where neither
    is finite the nearest pixel's in the row's order (left on ties), which
    is when the other pixels' brightness is needed.  ``law`` holds the
    focal length, principal point, k1, k2, the radius squared, the ambient
    level and the scale (at most 30 arguments: a call with more is not
    inlined).  Returns False where the chord samples hold a NaN (coverage
    undefined) and whether every ray converged.
    """
    K = px.shape[1]
    focal, principal, k1, k2, R2, ambient, scale = law[0], law[1], law[2], law[3], law[4], law[5], law[6]
    off, cov, shade, val = wk[0], wk[1], wk[2], wk[3]
    base = np.inf
    for k in range(K):
        off[k] = sg * (px[r, k] - at)
        base = min(base, off[k])
    if not ramp_histogram(c_lo[r], c_hi[r], c_w[r], base - 0.5, span, hwb[0], hwb[1]):
        return False, True
    rays_ok = True
    n_missing = 0
    for k in range(K):
        cov[k] = grid_coverage(hwb[0], hwb[1], int(np.rint(off[k] - base)))
        partial = cov[k] > 0.0 and cov[k] < 1.0 - 1e-9
        if partial and want_point:
            v_pt = 0.0
            c_pt = 0.0
            for i in range(frac.shape[0]):
                o = sg * ((px[r, k] - 0.5 + frac[i]) - at)
                v, c, ok = _limb_point(o, sg, edge_m, bg_row, width, cen_pt, nt_pt, hs_pt, nh_pt, focal, principal, k1, k2, R2, light, ambient, scale)
                rays_ok = rays_ok and ok
                v_pt += 0.0 if v != v else v
                c_pt += c
            point[r, k] = v_pt / c_pt if c_pt > 0.0 else np.nan
        # NaN: not evaluated yet (the surface is only where asked for)
        shade[k] = np.nan
        if partial and np.isfinite(point[r, k]):
            shade[k] = point[r, k]
        elif cov[k] > 0.0 and (k < n_use or run_lo <= k < run_hi):
            v, c, ok = _limb_point(max(off[k], 0.25), sg, edge_m, bg_row, width, cen_c, 1, hs_c, 1, focal, principal, k1, k2, R2, light, ambient, scale)
            rays_ok = rays_ok and ok
            shade[k] = v if c > 0.0 else np.nan
            if not np.isfinite(shade[k]):
                n_missing += 1
    if n_missing > 0:
        # the other pixels' surface too: the fill's candidates
        for k in range(K):
            if not (cov[k] > 0.0 and (k < n_use or run_lo <= k < run_hi)) and not np.isfinite(shade[k]):
                v, c, ok = _limb_point(max(off[k], 0.25), sg, edge_m, bg_row, width, cen_c, 1, hs_c, 1, focal, principal, k1, k2, R2, light, ambient, scale)
                rays_ok = rays_ok and ok
                shade[k] = v if c > 0.0 else np.nan
    for k in range(K):
        if cov[k] > 0.0 and (k < n_use or run_lo <= k < run_hi):
            s = shade[k]
            if not np.isfinite(s):
                # the nearest pixel with a brightness (none is missing then)
                best = -1
                for d in range(1, K):
                    if k - d >= 0 and np.isfinite(shade[k - d]):
                        best = k - d
                        break
                    if k + d < K and np.isfinite(shade[k + d]):
                        best = k + d
                        break
                if best >= 0:
                    s = shade[best]
            val[k] = s * cov[k]
        else:
            val[k] = 0.0
    return True, rays_ok


@jit(inline="always")
def _grid_span(px: np.ndarray) -> int:
    """The unit grid's span (pixels) over the rows' pixel centres ``px`` (R, K): the rows' offsets differ by whole pixels."""
    span = 0
    for r in range(px.shape[0]):
        lo_px = np.inf
        hi_px = -np.inf
        for k in range(px.shape[1]):
            lo_px = min(lo_px, px[r, k])
            hi_px = max(hi_px, px[r, k])
        span = max(span, int(np.rint(hi_px - lo_px)) + 1)
    return span


@jit(inline="always", error_model="numpy")
def _deep_ratio(val: np.ndarray, kw: int, n_level: int, nd: int) -> float:
    """The model's ratio of the run inside the level run to the level run (values ``val`` of the third profile)."""
    run_in = 0.0
    for k in range(kw, kw + n_level):
        run_in += val[k]
    run_deep = 0.0
    for k in range(kw + n_level, val.shape[0]):
        run_deep += val[k]
    return (run_deep / nd) / (run_in / n_level)


@jit(inline="always", error_model="numpy")
def _edge_variance(sw: np.ndarray, r: int, S_r: float, Lr: float, sl2_r: float, ratio: float) -> float:
    """The variance (px^2) of row ``r``'s edge from the window's sigmas ``sw[r]`` and the level's variance ``sl2_r``, at level ``Lr``."""
    Ls = Lr if Lr > 0.0 else 1.0
    s_w2 = 0.0
    for k in range(sw.shape[1]):
        s_w2 += sw[r, k] ** 2
    return s_w2 / Ls**2 + (S_r / Ls**2) ** 2 * sl2_r * ratio**2


@jit(inline="always", error_model="numpy")
def _model_ratio(val: np.ndarray, cov: np.ndarray, n_use: int, kw: int, n_level: int) -> tuple[float, float, bool]:
    """The model's window value per covered length over its level run's mean value, the window's covered length (px), and whether it is usable.

    The window is the first ``n_use`` of ``kw`` pixels of the profile's
    values ``val`` and coverages ``cov``, the level run the ``n_level``
    after them.  The ratio is usable within [0.5, 2] and on at least
    0.05 px of covered length; otherwise it is 1.
    """
    s_model = 0.0
    c_model = 0.0
    for k in range(kw):
        if k < n_use:
            s_model += val[k]
            c_model += cov[k]
    lev = 0.0
    for k in range(kw, kw + n_level):
        lev += val[k]
    ratio = s_model / c_model / (lev / n_level)
    usable = np.isfinite(ratio) and c_model > 0.05 and ratio >= 0.5 and ratio <= 2.0
    return (ratio if usable else 1.0), c_model, usable


@jit(inline="always")
def _accumulate(blurred: np.ndarray, w: float, cov: np.ndarray, val: np.ndarray) -> None:
    """Add ``w`` times a shifted profile's coverage and value to ``blurred``'s rows 0 and 1 (a blur node's share)."""
    for k in range(cov.shape[0]):
        blurred[0, k] += w * cov[k]
        blurred[1, k] += w * val[k]


@jit(error_model="numpy")
def limb_levels(
    sg: np.ndarray, px: np.ndarray, n_win: np.ndarray, kw: int, n_level: int,
    e0: np.ndarray, var0: np.ndarray, L0: np.ndarray, S: np.ndarray, L_run: np.ndarray, sl2: np.ndarray, sw: np.ndarray,
    q_data: np.ndarray, q_lim: np.ndarray, n_points: int, c_lo: np.ndarray, c_hi: np.ndarray, c_w: np.ndarray,
    t_rows: np.ndarray, edge_m: np.ndarray, sharp: np.ndarray, line_rows: np.ndarray, background: np.ndarray,
    tk: np.ndarray, hk: np.ndarray, focal: float, principal: float, k1: float, k2: float,
    pos: np.ndarray, vel: np.ndarray, acc: np.ndarray, t_c: float, radius_m: float, light: np.ndarray, ambient: float, scale: float,
    blur_shift: np.ndarray, blur_w: np.ndarray,
):
    """The edges' inner levels and edges from the shading model (:func:`ballscan.measure.edges._limb_levels`).

    Row ``r`` is an edge (side ``sg[r]``: +1 left, -1 right) with model-free
    edge ``e0``, variance ``var0`` (px^2) and level ``L0``, window sum ``S``
    and sigmas ``sw[r]`` (0 where padded), level run mean ``L_run`` and
    variance ``sl2`` (normalised units), the data's ratio ``q_data`` of the
    run inside the level run to the level run and its allowed difference
    from the model's ``q_lim`` (3 sigma plus the texture tolerance);
    its pixel centres ``px[r]`` (box pixels, the coordinates of ``e0``) are
    the window from its outermost pixel inwards (``kw`` columns, the first
    ``n_win[r]`` used), the ``n_level`` pixels of the level run and those of
    the run inside it.  The model (:meth:`ballscan.measure.shading.LimbProfile.rows`)
    gives each row its chord samples ``c_lo, c_hi, c_w`` (offsets inwards
    from its mean edge ``edge_m``, pixels: the same coordinates less the
    mean edge; NaN: the model has no edge), line time ``t_rows``, whether
    its edge is ``sharp`` (one point sample), its image line ``line_rows``
    in ``background`` (DN) and the shading law (see :func:`limb_values`; the
    camera's ``focal``, ``principal``, ``k1``, ``k2`` for the rays).

    Two rounds place the model's mean edge (the model-free edge, then the
    first round's), each taking the level ``L = L_run r``, ``r`` the
    model's ratio (:func:`_model_ratio`) and moving the edge by the
    model's covered length less the data's ``S / L``; the texture test
    compares ``q_data`` with the model's ratio at the new edge (within
    ``q_lim``).  Rows that fail keep ``e0, var0, L0``.  ``n_points`` point
    samples per partly covered pixel.  A lens's blur along the sensor
    (``blur_shift`` pixels, weights ``blur_w``:
    :func:`ballscan.model.blur.semicircle_nodes`; one shift 0 of weight 1
    for none) averages each pixel's value and coverage over the profile
    moved by those shifts, the brightness at each shift the surface's there.

    Returns
    -------
    edge, var, L : ndarray (R,)
    rays_ok : bool
        False when the inverse distortion of a ray did not converge.
    """
    R, K = px.shape
    nb = blur_shift.shape[0]
    blurred = np.empty((2, K))
    nd = K - kw - n_level
    edge = e0.copy()
    var = var0.copy()
    L = L0.copy()
    # the unit grid's span: the rows' offsets differ by whole pixels
    span = _grid_span(px)
    hwb = np.empty((2, span + 2))
    frac = (np.arange(n_points) + 0.5) / n_points
    point = np.full((R, K), np.nan)
    wk = np.empty((4, K))
    cov, val = wk[1], wk[3]
    R2 = radius_m * radius_m
    has_acc = acc[0] != 0.0 or acc[1] != 0.0 or acc[2] != 0.0
    width = background.shape[1]
    law = np.array([focal, principal, k1, k2, R2, ambient, scale])
    cen_pt, hs_pt = np.empty((max(tk.shape[0], 1), 4)), np.empty(max(hk.shape[0], 1))
    cen_c, hs_c = np.empty((1, 4)), np.empty(1)
    rays_ok = True
    for r in range(R):
        if not np.isfinite(edge_m[r]):
            continue
        bg_row = background[line_rows[r]]
        # the row's sphere centres: the point samples' and the surface's (one)
        nt_pt = _centres(t_rows[r], sharp[r], tk, pos, vel, acc, has_acc, t_c, cen_pt)
        nh_pt = _heights(sharp[r], hk, focal, hs_pt)
        _centres(t_rows[r], True, tk, pos, vel, acc, has_acc, t_c, cen_c)
        _heights(True, hk, focal, hs_c)
        er = e0[r]
        ratio = 1.0
        Lr = L_run[r]
        usable = False
        fine = True
        for rnd in range(3):
            at = er
            # the window's and the level run's values, then the runs' (the texture test)
            n_use, run_hi = (n_win[r], kw + n_level) if rnd < 2 else (0, K)
            if nb > 1:
                blurred[:] = 0.0
            for j in range(nb):
                # the profile moved by the blur's shift (its partly covered pixels' brightness there)
                fine, ok = _limb_row_profile(
                    r, at - sg[r] * blur_shift[j], sg[r], px, c_lo, c_hi, c_w, span, hwb, frac, rnd == 0 or nb > 1, point, wk, n_use, kw,
                    run_hi, edge_m[r], bg_row, width, cen_pt, nt_pt, hs_pt, nh_pt, cen_c, hs_c, law, light,
                )
                rays_ok = rays_ok and ok
                if not fine:
                    break
                if nb > 1:
                    _accumulate(blurred, blur_w[j], cov, val)
            if not fine:
                break
            if nb > 1:
                cov[:] = blurred[0]
                val[:] = blurred[1]
            if rnd == 2:
                break
            ratio, c_model, usable = _model_ratio(val, cov, n_win[r], kw, n_level)
            Lr = L_run[r] * ratio
            covered = S[r] / (Lr if Lr > 0.0 else 1.0)
            er = at + sg[r] * (c_model - covered) if usable else e0[r]
        if not fine:
            # no coverage (a NaN chord sample): the model-free edge
            continue
        # texture test with the model at the new edge (the third profile)
        smooth = abs(q_data[r] - _deep_ratio(val, kw, n_level, nd)) <= q_lim[r]
        if usable and smooth:
            edge[r] = er
            var[r] = _edge_variance(sw, r, S[r], Lr, sl2[r], ratio)
            L[r] = Lr
    return edge, var, L, rays_ok


@jit(inline="always")
def _huber_weights(r: np.ndarray, huber_k: float, w: np.ndarray, buf: np.ndarray) -> float:
    """The robust scale (1.4826 MAD, floored at 1e-9) of residuals ``r`` and their Huber weights at ``huber_k`` of it into ``w`` (the Huber rounds of :func:`ballscan.measure.shading.fit_shading`)."""
    med = np.median(r)
    for i in range(r.shape[0]):
        buf[i] = abs(r[i] - med)
    scale = max(1.4826 * np.median(buf), 1e-9)
    ks = huber_k * scale
    for i in range(r.shape[0]):
        a = abs(r[i]) / ks
        w[i] = 1.0 if a <= 1.0 else 1.0 / max(a, 1e-12)
    return scale


@jit()
def shading_fit(y: np.ndarray, normals: np.ndarray, huber_k: float, n_iterations: int, diverged: float, flat_tol: float):
    """The robust fit of ``I = A + max(0, n . b)`` to interior pixels (:func:`ballscan.measure.shading.fit_shading`).

    ``y`` (N,) the pixels (DN), ``normals`` (N, 3) the unit surface normals
    they see.  Each of ``n_iterations`` rounds solves the weighted least
    squares of the law, linear in ``(A, b)`` on the pixels the last round
    lit (``n . b > 0``; the others see ``A`` only), and reweights by Huber at
    ``huber_k`` robust sigmas (1.4826 x the MAD) of the residuals; the best
    round (least robust scale) is kept when the last one's scale exceeds
    ``diverged`` times it.  The flat law (Huber mean, the same rounds)
    replaces it unless the light lowers the robust scale by more than
    ``flat_tol`` below the flat law's.

    Returns
    -------
    coef : ndarray (4,)
        ``(A, b_x, b_y, b_z)``, DN.
    scale : float
        Robust scale of the residuals, DN.
    """
    N = y.shape[0]
    w = np.ones(N)
    active = np.ones(N, dtype=np.bool_)
    coef = np.zeros(4)
    scale = 1.0
    best_scale = np.inf
    best_coef = coef
    A = np.empty((N, 4))
    b = np.empty(N)
    r = np.empty(N)
    buf = np.empty(N)
    # numpy's lstsq cut-off (rcond=None)
    rcond = np.finfo(np.float64).eps * max(N, 4)
    for _ in range(n_iterations):
        for i in range(N):
            sw = math.sqrt(w[i])
            A[i, 0] = sw
            for j in range(3):
                A[i, j + 1] = normals[i, j] * sw if active[i] else 0.0
            b[i] = y[i] * sw
        coef = np.linalg.lstsq(A, b, rcond)[0]
        lit = np.dot(normals, coef[1:].copy())
        for i in range(N):
            active[i] = lit[i] > 0.0
            r[i] = y[i] - coef[0] - max(lit[i], 0.0)
        scale = _huber_weights(r, huber_k, w, buf)
        if scale < best_scale:
            best_scale = scale
            best_coef = coef
    if scale > diverged * best_scale:
        # the rounds are a fixed-point iteration, not a descent: keep the best
        scale = best_scale
        coef = best_coef
    # the flat law: a Huber mean
    for i in range(N):
        w[i] = 1.0
    level = pairwise_sum(y) / N
    flat_scale = 1.0
    for _ in range(n_iterations):
        for i in range(N):
            b[i] = w[i] * y[i]
        level = pairwise_sum(b) / pairwise_sum(w)
        for i in range(N):
            r[i] = y[i] - level
        flat_scale = _huber_weights(r, huber_k, w, buf)
    if flat_scale <= (1.0 + flat_tol) * scale:
        coef = np.zeros(4)
        coef[0] = level
        scale = flat_scale
    return coef, scale


@jit(error_model="numpy")
def line_level_sums(
    offsets: np.ndarray,
    inside: np.ndarray,
    edge_m: np.ndarray,
    t_rows: np.ndarray,
    sharp: np.ndarray,
    line_rows: np.ndarray,
    background: np.ndarray,
    tk: np.ndarray,
    hk: np.ndarray,
    focal: float,
    principal: float,
    k1: float,
    k2: float,
    pos: np.ndarray,
    vel: np.ndarray,
    acc: np.ndarray,
    t_c: float,
    radius_m: float,
    light: np.ndarray,
    ambient: float,
    scale: float,
):
    """Sums of the model's normalised value and coverage over the ``inside`` positions of each row (:meth:`ballscan.measure.shading.LimbProfile.line_levels`).

    Row ``r`` is the left edge of image line ``line_rows[r]`` (mean edge
    ``edge_m[r]``, pixels; NaN: the model does not see the ball, the sums
    NaN where a position is inside), its positions ``offsets[r]`` pixels
    inwards from it; each position's value and coverage are the means over
    the samples of :func:`limb_values` (one at the line's centre time where
    ``sharp``); the model's arguments are those of :func:`limb_levels` from
    ``background`` on.

    Returns
    -------
    val_sum, cov_sum : ndarray (R,)
    rays_ok : bool
        False when the inverse distortion of a ray did not converge.
    """
    R, C = offsets.shape
    val_sum = np.empty(R)
    cov_sum = np.empty(R)
    bv = np.empty(C)
    bc = np.empty(C)
    cen = np.empty((max(tk.shape[0], 1), 4))
    hs = np.empty(max(hk.shape[0], 1))
    R2 = radius_m * radius_m
    has_acc = acc[0] != 0.0 or acc[1] != 0.0 or acc[2] != 0.0
    width = background.shape[1]
    rays_ok = True
    for r in range(R):
        if not np.isfinite(edge_m[r]):
            any_in = False
            for k in range(C):
                any_in = any_in or inside[r, k]
            val_sum[r] = np.nan if any_in else 0.0
            cov_sum[r] = val_sum[r]
            continue
        bg_row = background[line_rows[r]]
        nt = _centres(t_rows[r], sharp[r], tk, pos, vel, acc, has_acc, t_c, cen)
        nh = _heights(sharp[r], hk, focal, hs)
        for k in range(C):
            bv[k] = 0.0
            bc[k] = 0.0
            if inside[r, k]:
                v, c, ok = _limb_point(offsets[r, k], 1.0, edge_m[r], bg_row, width, cen, nt, hs, nh, focal, principal, k1, k2, R2, light, ambient, scale)
                rays_ok = rays_ok and ok
                bv[k] = v
                bc[k] = c
        val_sum[r] = pairwise_sum(bv)
        cov_sum[r] = pairwise_sum(bc)
    return val_sum, cov_sum, rays_ok


@jit(error_model="numpy")
def level_scatter(
    lines_img: np.ndarray,
    lo: np.ndarray,
    count: np.ndarray,
    rows: np.ndarray,
    profile: np.ndarray,
    profile_sigma: np.ndarray,
    c0: int,
    edge_m: np.ndarray,
    t_rows: np.ndarray,
    background: np.ndarray,
    tk: np.ndarray,
    hk: np.ndarray,
    focal: float,
    principal: float,
    k1: float,
    k2: float,
    pos: np.ndarray,
    vel: np.ndarray,
    acc: np.ndarray,
    t_c: float,
    radius_m: float,
    light: np.ndarray,
    ambient: float,
    scale: float,
):
    """The relative scatter of lines' mean brightness about the model's, pixel noise removed (:func:`ballscan.measure.shading._line_level_scatter`).

    Line ``i`` (image line ``lines_img[i]``, row ``rows[i]`` of the edges'
    normalised ``profile`` and its sigmas, whose column 0 is sensor pixel
    ``c0``) is measured over the ``count[i]`` columns from ``lo[i]``, where
    the profile is finite and the model (its surface at the line's centre
    time, mean left edge ``edge_m[i]``: offsets ``u - edge_m``) sees the
    ball: ``d = mean(p) / mean(model) - 1`` and its noise ``v = sum(sigma^2)
    / n^2 / mean(model)^2``, on lines with at least 3 such pixels, finite
    ``d, v`` and a model mean above 0.05.  Model arguments as for
    :func:`limb_levels` from ``background`` on.

    Returns
    -------
    scatter : float
        ``sqrt(max(mean(d^2) - mean(v), 0))``; NaN when fewer than 3 lines
        qualify.
    length : float
        Mean number of pixels per line it was measured over (1 with NaN).
    rays_ok : bool
        False when the inverse distortion of a ray did not converge.
    """
    L = lo.shape[0]
    C = 0
    for i in range(L):
        C = max(C, count[i])
    bp = np.empty(C)
    bm = np.empty(C)
    bs = np.empty(C)
    d = np.empty(L)
    v = np.empty(L)
    n_px = np.empty(L)
    cen = np.empty((1, 4))
    hs = np.empty(1)
    R2 = radius_m * radius_m
    has_acc = acc[0] != 0.0 or acc[1] != 0.0 or acc[2] != 0.0
    width = background.shape[1]
    rays_ok = True
    n_good = 0
    for i in range(L):
        for k in range(C):
            bp[k] = 0.0
            bm[k] = 0.0
            bs[k] = 0.0
        n = 0
        if np.isfinite(edge_m[i]):
            bg_row = background[lines_img[i]]
            _centres(t_rows[i], True, tk, pos, vel, acc, has_acc, t_c, cen)
            _heights(True, hk, focal, hs)
            for k in range(count[i]):
                col = lo[i] + k
                p = profile[rows[i], col]
                if not np.isfinite(p):
                    continue
                val, hit, ok = _limb_point(
                    float(col + c0) - edge_m[i], 1.0, edge_m[i], bg_row, width, cen, 1, hs, 1, focal, principal, k1, k2, R2, light, ambient, scale
                )
                rays_ok = rays_ok and ok
                if hit > 0.0:
                    bp[k] = p
                    bm[k] = val
                    bs[k] = profile_sigma[rows[i], col] ** 2
                    n += 1
        if n < 3:
            continue
        m_mean = pairwise_sum(bm) / n
        di = pairwise_sum(bp) / n / m_mean - 1.0
        vi = pairwise_sum(bs) / (n * n) / m_mean**2
        if np.isfinite(di) and np.isfinite(vi) and m_mean > 0.05:
            d[n_good] = di * di
            v[n_good] = vi
            n_px[n_good] = n
            n_good += 1
    if n_good < 3:
        return np.nan, 1.0, rays_ok
    return math.sqrt(max(pairwise_sum(d[:n_good]) / n_good - pairwise_sum(v[:n_good]) / n_good, 0.0)), pairwise_sum(n_px[:n_good]) / n_good, rays_ok


@jit()
def interior_normals(
    t_rows: np.ndarray,
    cols: np.ndarray,
    lines: np.ndarray,
    usable: np.ndarray,
    origin_line: int,
    origin_col: int,
    focal: float,
    principal: float,
    k1: float,
    k2: float,
    pos: np.ndarray,
    vel: np.ndarray,
    acc: np.ndarray,
    t_c: float,
    radius_m: float,
):
    """Which pixels see the ball and its unit normals there (:func:`ballscan.measure.shading.surface_normals` at the pixels' centres, for :func:`ballscan.measure.shading.fit_shading`).

    Pixel ``i`` is column ``cols[i]`` of image line ``lines[i]`` at time
    ``t_rows[i]`` (s); its ray through the pixel's centre meets the sphere
    (the same arithmetic as :func:`_limb_rays`) and it is ``usable``
    (``usable[line - origin_line, col - origin_col]``, False outside the box;
    an empty ``usable`` allows every pixel).

    Returns
    -------
    hit : ndarray of bool (P,)
    normals : ndarray (P, 3)
        Outward unit normals where ``hit``.
    rays_ok : bool
        False when the inverse distortion of a ray did not converge.
    """
    P = cols.shape[0]
    hit = np.zeros(P, dtype=np.bool_)
    normals = np.zeros((P, 3))
    R2 = radius_m * radius_m
    has_acc = acc[0] != 0.0 or acc[1] != 0.0 or acc[2] != 0.0
    check = usable.shape[0] > 0
    cen = np.empty((1, 4))
    no_instants = np.zeros(0)
    rays_ok = True
    for i in range(P):
        if check:
            rb = lines[i] - origin_line
            cb = cols[i] - origin_col
            if rb < 0 or rb >= usable.shape[0] or cb < 0 or cb >= usable.shape[1] or not usable[rb, cb]:
                continue
        nu, ok = normalised(float(cols[i]), focal, principal, k1, k2)
        rays_ok = rays_ok and ok
        _centres(t_rows[i], True, no_instants, pos, vel, acc, has_acc, t_c, cen)
        hit_i, nx, ny, nz = _ray_normal(0.0 / focal, nu, cen[0, 0], cen[0, 1], cen[0, 2], cen[0, 3], R2)
        if hit_i:
            hit[i] = True
            normals[i, 0] = nx
            normals[i, 1] = ny
            normals[i, 2] = nz
    return hit, normals, rays_ok


@jit()
def chord_rows(u_lo: np.ndarray, u_hi: np.ndarray, wgt: np.ndarray, left: np.ndarray, right: np.ndarray, inv: np.ndarray, sg: np.ndarray):
    """The chord samples of rows as offsets inwards from their edge (:meth:`ballscan.measure.shading.LimbProfile._chords`).

    ``u_lo, u_hi, wgt`` (U, S) the samples' ends (pixels) and weights of
    ``U`` lines, ``left, right`` (U,) their mean edges, ``inv`` (R,) each
    row's line and ``sg`` (R,) its side (> 0 the left edge; else, NaN
    too, the right one).  Returns ``lo, hi, w`` (R, S):
    ``np.where(sg > 0, u_lo - left, right - u_hi)``, ``np.where(sg > 0, u_hi
    - left, right - u_lo)`` and the weights, of each row's line.
    """
    R = inv.shape[0]
    S = u_lo.shape[1]
    lo = np.empty((R, S))
    hi = np.empty((R, S))
    w = np.empty((R, S))
    for r in range(R):
        k = inv[r]
        if sg[r] > 0:
            e = left[k]
            for j in range(S):
                lo[r, j] = u_lo[k, j] - e
                hi[r, j] = u_hi[k, j] - e
        else:
            e = right[k]
            for j in range(S):
                lo[r, j] = e - u_hi[k, j]
                hi[r, j] = e - u_lo[k, j]
        for j in range(S):
            w[r, j] = wgt[k, j]
    return lo, hi, w


@jit()
def unique_lines(lines: np.ndarray):
    """``np.unique(lines, return_inverse=True)`` of a non-empty array of integers spanning a short range (a table of the range: no sort)."""
    first = lines.min()
    rank = np.zeros(lines.max() - first + 1, dtype=np.int64)
    for i in range(lines.shape[0]):
        rank[lines[i] - first] = 1
    k = 0
    for j in range(rank.shape[0]):
        if rank[j]:
            rank[j] = k
            k += 1
    uniq = np.empty(k, dtype=np.int64)
    inv = np.empty(lines.shape[0], dtype=np.int64)
    for i in range(lines.shape[0]):
        inv[i] = rank[lines[i] - first]
        uniq[inv[i]] = lines[i]
    return uniq, inv


@jit(inline="always")
def _nan_to_num(x: float) -> float:
    """``np.nan_to_num`` of one float64."""
    if x != x:
        return 0.0
    if x == np.inf:
        return 1.7976931348623157e308
    if x == -np.inf:
        return -1.7976931348623157e308
    return x


@jit()
def level_spans(left: np.ndarray, right: np.ndarray, spread: np.ndarray, m: int):
    """The sampled span of each line for :meth:`ballscan.measure.shading.LimbProfile.line_levels`.

    Returns ``pad = nan_to_num(spread) / 2 + 1.5`` and ``span =
    nan_to_num(right - left) + 2 pad`` (R,), and ``max(span) * m`` (NaN
    where a span is not finite), with numpy's arithmetic.
    """
    R = left.shape[0]
    pad = np.empty(R)
    span = np.empty(R)
    top = -np.inf
    finite = True
    for r in range(R):
        pad[r] = _nan_to_num(spread[r]) / 2.0 + 1.5
        span[r] = _nan_to_num(right[r] - left[r]) + 2.0 * pad[r]
        finite = finite and math.isfinite(span[r])
        top = max(top, span[r])
    return pad, span, top * m if finite else np.nan


def warm_up() -> None:
    """Load (or compile) this module's kernels now, on tiny inputs (see :func:`ballscan.pipeline.warmup.warm_up`)."""
    th = np.array([0.0, 0.0, 3.0, 30.0, 0.0, 0.0])
    k0 = np.zeros(1, dtype=np.int64)
    yes = np.ones(1, dtype=np.bool_)
    z1 = np.zeros(1)
    limb_values(
        np.zeros(1), np.zeros((1, 1)), np.zeros((1, 1)), np.ones(1, dtype=np.bool_), np.zeros(1), np.zeros(1),
        3000.0, th[:3].copy(), th[3:].copy(), np.zeros(3), 0.0, 0.03, np.ones(3), 0.0, 1.0,
    )
    limb_levels(
        np.ones(1), np.zeros((1, 3)), np.ones(1, dtype=np.int64), 1, 1, z1, z1, z1, z1, np.ones(1), z1, np.zeros((1, 1)), z1, z1, 1,
        np.zeros((1, 1)), np.ones((1, 1)), np.ones((1, 1)), z1, z1, yes, k0, np.zeros((1, 1)), z1, z1,
        3000.0, 0.0, 0.0, 0.0, th[:3].copy(), th[3:].copy(), np.zeros(3), 0.0, 0.03, np.ones(3), 0.0, 1.0, z1, np.ones(1),
    )
    shading_fit(np.arange(8.0), np.tile(np.array([0.6, 0.0, -0.8]), (8, 1)), 1.5, 1, 1.5, 0.01)
    law = (3000.0, 0.0, 0.0, 0.0, th[:3].copy(), th[3:].copy(), np.zeros(3), 0.0, 0.03, np.ones(3), 0.0, 1.0)
    line_level_sums(np.zeros((1, 1)), np.ones((1, 1), dtype=np.bool_), z1, z1, yes, k0, np.zeros((1, 1)), z1, z1, *law)
    interior_normals(z1, k0, k0, np.zeros((0, 0), dtype=np.bool_), 0, 0, *law[:4], *law[4:9])
    level_scatter(k0, k0, np.ones(1, dtype=np.int64), k0, np.ones((1, 1)), np.ones((1, 1)), 0, z1, z1, np.zeros((1, 1)), z1, z1, *law)
    chord_rows(np.zeros((1, 2)), np.zeros((1, 2)), np.ones((1, 2)), z1, z1, k0, np.ones(1))
    unique_lines(k0)
    level_spans(z1, z1, z1, 2)
