"""Compiled loops of the averaged silhouette: its chord samples, edges, pixel residuals and their Jacobians.

The fit, the shading pass and the bounds evaluate the averaged silhouette
(:func:`ballscan.model.averaged.averaged_model`) tens of times per ball on a few
thousand chord samples.  As numpy expressions that is some hundred array
operations per call, whose fixed cost (a few microseconds each) dominates
on a ball's hundred lines; one loop over the samples does the same
arithmetic in one call.  The mathematics is that of
:func:`ballscan.model.silhouette.silhouette` with ``model="averaged"`` (see
its Notes; :func:`ballscan.model.averaged._model_core` documents the layout),
which the tests compare it against.  The pixel model's coverage of a row's
pixels by its chords is :mod:`ballscan.model.coverage`'s.
"""

from __future__ import annotations

import math

import numpy as np

from ..compiled import jit
from ..geometry.lens import distortion_slope, project
from .coverage import grid_coverage, ramp_histogram


@jit(inline="always")
def _line_centre(dt0, y0, z0, vx, vy, vz, ax, ay, az, has_acc):
    """The ball centre's ``(x, y, z)`` (m) at ``dt0`` (s) from the crossing, and its speed along x (m/s)."""
    if has_acc:
        h2 = 0.5 * dt0 * dt0
        x0 = vx * dt0 + ax * h2
        z_line = z0 + vz * dt0 + az * h2
        y_line = y0 + vy * dt0 + ay * h2
        a1 = vx + ax * dt0
    else:
        x0 = vx * dt0
        z_line = z0 + vz * dt0
        y_line = y0 + vy * dt0
        a1 = vx
    return x0, y_line, z_line, a1


@jit(inline="always")
def _tangent_terms(xc, yc, zc, d, rho):
    """The terms of the two tangents to one chord sample's section (:func:`ballscan.model.silhouette.tangent_normalised`, as the averaged model's numpy form).

    The sample's plane ``x = s z`` with ``s = (xc - d) / zc`` (``zc`` 1
    where not positive) cuts the sphere of centre ``(xc, yc, zc)`` in a
    circle of radius ``rho`` (m) at in-plane depth ``w = zc + s xc`` (m);
    its tangents are ``n_pm = (yc w +- rho root) inv_den``.  Returns ``ok``
    (the tangents exist and point forwards), ``s``, ``w``, ``root = sqrt(yc^2
    + w^2 - rho^2)`` and ``inv_den = 1 / (w^2 - rho^2)`` (1 and 0 where not
    ``ok``).
    """
    s = (xc - d) / (zc if zc > 0.0 else 1.0)
    w = zc + s * xc
    den = w * w - rho * rho
    disc = yc * yc + den
    ok = (w > rho) and (disc > 0.0)
    if ok:
        return True, s, w, math.sqrt(disc), 1.0 / den
    return False, s, w, 1.0, 0.0


@jit(inline="always")
def _chord_samples(te, g, gw, R, x0, dt0, A, B, a1, y0, z0, vx, vy, vz, ax, ay, az, has_acc, focal_px, principal_px, k1, k2, ulo, uhi, wok):
    """One line's chord samples of :func:`averaged_samples`, into ``ulo, uhi, wok`` (3 * n_nodes).

    The quadrature over the three kink segments ``te`` (4, overwritten by
    their angles) of the exposure's blur (half-widths ``A`` along the
    motion, ``B`` across the pixel, m); returns the samples' total weight,
    their weighted edge sums (pixels) and whether a weighted sample missed
    the ball's tangent.
    """
    nn = g.shape[0]
    AmB = abs(A - B)
    ApB = A + B
    te[0] = x0 - ApB
    te[1] = x0 - AmB
    te[2] = x0 + AmB
    te[3] = x0 + ApB
    for k in range(4):
        te[k] = math.asin(min(max(te[k], -R), R) / R)
    plateau = 1.0 / max(2.0 * max(A, B), 1e-300)
    inv4AB = 1.0 / max(4.0 * A * B, 1e-300)
    inv_a1 = 1.0 / a1 if a1 != 0.0 else 0.0
    mass = 0.0
    sum_lo = 0.0
    sum_hi = 0.0
    invalid = False
    for q in range(3):
        half = (te[q + 1] - te[q]) / 2.0
        for i in range(nn):
            ang = te[q] + half * (1.0 + g[i])
            d = R * math.sin(ang)
            rho = R * math.cos(ang)
            jac = rho * (half * gw[i])
            dd = d - x0
            dist = abs(dd)
            if dist > AmB:
                dens = max(ApB - dist, 0.0) * inv4AB
            else:
                dens = plateau
            if not ApB > 0.0:
                dens = 0.0
            wgt = dens * jac
            u_mean = 0.5 * (max(-A, dd - B) + min(A, dd + B))
            dts = u_mean * inv_a1 + dt0
            xc = vx * dts
            yc = y0 + vy * dts
            zc = z0 + vz * dts
            if has_acc:
                h2s = 0.5 * dts * dts
                xc = xc + ax * h2s
                yc = yc + ay * h2s
                zc = zc + az * h2s
            ok, _, w, root, inv_den = _tangent_terms(xc, yc, zc, d, rho)
            j = q * nn + i
            if not ok and wgt > 0.0:
                invalid = True
            a_ = yc * w
            b_ = rho * root
            lo = project((a_ - b_) * inv_den, focal_px, principal_px, k1, k2)
            hi = project((a_ + b_) * inv_den, focal_px, principal_px, k1, k2)
            wk = wgt if ok else 0.0
            ulo[j] = lo
            uhi[j] = hi
            wok[j] = wk
            mass += wk
            sum_lo += wk * lo
            sum_hi += wk * hi
    return mass, sum_lo, sum_hi, invalid


@jit()
def _blurred_chord_samples(
    te, g, gw, R, x0, dt0, A, B, a1, y0, z0, vx, vy, vz, ax, ay, az, has_acc, focal_px, principal_px, k1, k2, ulo, uhi, wok, blur_px, blur_w,
    m_per_px,
):
    """:func:`_chord_samples` over the blur's offsets across the sensor, each weighed by ``blur_w``.

    Offset ``b`` moves the viewing plane by ``blur_px[b] * m_per_px``
    metres (the line's depth over the focal length); its samples are at
    ``b * 3 n_nodes`` on.  Returns the total weight, the weighted edge sums
    (pixels) and whether a weighted sample missed the ball's tangent.
    """
    S1 = 3 * g.shape[0]
    mass = 0.0
    sum_lo = 0.0
    sum_hi = 0.0
    invalid = False
    for b in range(blur_px.shape[0]):
        part = slice(b * S1, (b + 1) * S1)
        m_b, lo_b, hi_b, bad = _chord_samples(
            te, g, gw, R, x0 - blur_px[b] * m_per_px, dt0, A, B, a1, y0, z0, vx, vy, vz, ax, ay, az, has_acc, focal_px, principal_px, k1, k2,
            ulo[part], uhi[part], wok[part],
        )
        wb = blur_w[b]
        mass += wb * m_b
        sum_lo += wb * lo_b
        sum_hi += wb * hi_b
        invalid = invalid or bad
        wok[part] *= wb
    return mass, sum_lo, sum_hi, invalid


@jit()
def averaged_samples(
    th: np.ndarray,
    t: np.ndarray,
    radius_m: float,
    exposure_s: float,
    focal_px: float,
    principal_px: float,
    k1: float,
    k2: float,
    acc: np.ndarray,
    g: np.ndarray,
    gw: np.ndarray,
    full: bool,
    want_samples: bool,
    blur_px: np.ndarray,
    blur_w: np.ndarray,
):
    """The averaged silhouette of parameter sets ``th`` (P, 6) at line times ``t`` (1 or P, N).

    Returns ``(left, right, presence, area, spread, valid, u_lo, u_hi,
    wgt)``: per line (P, N), and per sample (P, N, 3 * n_nodes * B) when
    ``want_samples`` (else arrays of size 0).  ``spread`` and ``valid``
    are computed only with ``full`` (else 0 and True).  A lens's blur
    across the sensor (the B offsets ``blur_px``, pixels, and weights
    ``blur_w`` of its marginal: :func:`ballscan.model.averaged.blur_offsets`;
    one offset 0 of weight 1 for none) widens the pixel's height: each of
    its offsets moves the viewing plane by as much at the line's depth.
    """
    P = th.shape[0]
    N = t.shape[1]
    nn = g.shape[0]
    nb = blur_px.shape[0]
    S1 = 3 * nn
    S = S1 * nb
    reach_px = 0.0
    for b in range(nb):
        reach_px = max(reach_px, abs(blur_px[b]))
    R = radius_m
    ax, ay, az = acc[0], acc[1], acc[2]
    has_acc = ax != 0.0 or ay != 0.0 or az != 0.0
    left = np.empty((P, N))
    right = np.empty((P, N))
    presence = np.empty((P, N))
    area = np.empty((P, N))
    spread = np.zeros((P, N))
    valid = np.ones((P, N), dtype=np.bool_)
    if want_samples:
        s_lo = np.empty((P, N, S))
        s_hi = np.empty((P, N, S))
        s_w = np.empty((P, N, S))
    else:
        s_lo = np.empty((0, 0, 0))
        s_hi = np.empty((0, 0, 0))
        s_w = np.empty((0, 0, 0))
    ulo = np.empty(S)
    uhi = np.empty(S)
    wok = np.empty(S)
    te = np.empty(4)
    for p in range(P):
        tc, y0, z0, vx, vy, vz = th[p, 0], th[p, 1], th[p, 2], th[p, 3], th[p, 4], th[p, 5]
        tp = 0 if t.shape[0] == 1 else p
        for n in range(N):
            dt0 = t[tp, n] - tc
            x0, y_line, z_line, a1 = _line_centre(dt0, y0, z0, vx, vy, vz, ax, ay, az, has_acc)
            A = abs(a1) * (exposure_s / 2.0)
            B = max(z_line, 0.0) / (2.0 * focal_px)
            m_per_px = max(z_line, 0.0) / focal_px
            ApB = A + B + reach_px * m_per_px
            if not want_samples and (x0 - ApB >= R or x0 + ApB <= -R):
                # the line misses the ball: every kink clips to the same pole,
                # every sample weighs 0 (the loop below gives these values)
                u_c = project(y_line / (z_line if z_line > 0.0 else 1.0), focal_px, principal_px, k1, k2)
                left[p, n] = u_c
                right[p, n] = u_c
                area[p, n] = 0.0
                presence[p, n] = 0.0
                if full:
                    spread[p, n] = 0.0
                    valid[p, n] = z_line > 0.0
                continue
            if nb == 1:
                mass, sum_lo, sum_hi, invalid = _chord_samples(
                    te, g, gw, R, x0 - blur_px[0] * m_per_px, dt0, A, B, a1, y0, z0, vx, vy, vz, ax, ay, az, has_acc, focal_px, principal_px,
                    k1, k2, ulo, uhi, wok,
                )
            else:
                mass, sum_lo, sum_hi, invalid = _blurred_chord_samples(
                    te, g, gw, R, x0, dt0, A, B, a1, y0, z0, vx, vy, vz, ax, ay, az, has_acc, focal_px, principal_px, k1, k2, ulo, uhi, wok,
                    blur_px, blur_w, m_per_px,
                )
            present = mass > 0.0
            inv_m = 1.0 / mass if present else 1.0
            lft = sum_lo * inv_m
            rgt = sum_hi * inv_m
            area[p, n] = sum_hi - sum_lo
            presence[p, n] = min(mass, 1.0)
            if full:
                var_l = 0.0
                var_r = 0.0
                for j in range(S):
                    dl = ulo[j] - lft
                    dr = uhi[j] - rgt
                    var_l += wok[j] * dl * dl
                    var_r += wok[j] * dr * dr
                spread[p, n] = math.sqrt(max(var_l * inv_m, var_r * inv_m))
                valid[p, n] = (z_line > 0.0) and not invalid
            if not present:
                # absent lines: both edges at the centre's projection (the limit of a vanishing cap)
                u_c = project(y_line / (z_line if z_line > 0.0 else 1.0), focal_px, principal_px, k1, k2)
                lft = u_c
                rgt = u_c
            left[p, n] = lft
            right[p, n] = rgt
            if want_samples:
                for j in range(S):
                    s_lo[p, n, j] = ulo[j]
                    s_hi[p, n, j] = uhi[j]
                    s_w[p, n, j] = wok[j]
    return left, right, presence, area, spread, valid, s_lo, s_hi, s_w


@jit()
def _row_grids(cols: np.ndarray, mask: np.ndarray):
    """Each row's first used column (its unit grid's origin, pixels) and the widest row's span (pixels) of ``cols, mask`` (Np, K)."""
    Np, K = cols.shape
    base = np.empty(Np)
    span = 0
    for r in range(Np):
        lo_c = np.inf
        hi_c = -np.inf
        for k in range(K):
            if mask[r, k]:
                lo_c = min(lo_c, cols[r, k])
                hi_c = max(hi_c, cols[r, k])
        base[r] = lo_c if lo_c <= hi_c else 0.0
        if lo_c <= hi_c:
            span = max(span, int(round(hi_c - lo_c)) + 1)
    return base, span


@jit()
def pixel_residuals(
    s_lo: np.ndarray,
    s_hi: np.ndarray,
    s_w: np.ndarray,
    cols: np.ndarray,
    mask: np.ndarray,
    shade: np.ndarray,
    w: np.ndarray,
    p: np.ndarray,
    group: np.ndarray,
    n_groups: int,
    n_out: int,
) -> np.ndarray:
    """Whitened pixel residuals ``(B_g s cov - p) w`` of ``P`` parameter sets (:func:`ballscan.model.pixels.pixel_residuals`).

    ``s_lo, s_hi, s_w`` (P, Np, S) are the chord samples of the fitted
    lines; ``cols, mask, shade, w, p, group`` (Np, K) the pixels' centres,
    use, relative surface brightness, weight, value and brightness group.
    ``cov`` is the sum over the samples of weight times the overlap of the
    chord with ``[col - 1/2, col + 1/2]``; ``B_g`` the least-squares
    brightness of group ``g`` (variable projection).  Residuals in the
    row-major order of ``mask`` (``n_out`` of them), (P, n_out).
    """
    P = s_lo.shape[0]
    Np, K = cols.shape
    S = s_lo.shape[2]
    out = np.empty((P, n_out))
    c = np.empty(n_out)
    num = np.empty(n_groups)
    den = np.empty(n_groups)
    # each row's pixels on a unit grid from its first column (ramp_histogram)
    base, span = _row_grids(cols, mask)
    hw = np.empty(span + 2)
    hwf = np.empty(span + 2)
    for q in range(P):
        num[:] = 0.0
        den[:] = 0.0
        m = 0
        for r in range(Np):
            ok = ramp_histogram(s_lo[q, r], s_hi[q, r], s_w[q, r], base[r] - 0.5, span, hw, hwf)
            for k in range(K):
                if not mask[r, k]:
                    continue
                cov = grid_coverage(hw, hwf, int(round(cols[r, k] - base[r]))) if ok else np.nan
                ck = cov * shade[r, k]
                c[m] = ck
                ww = w[r, k] * w[r, k]
                gi = group[r, k]
                num[gi] += ck * p[r, k] * ww
                den[gi] += ck * ck * ww
                m += 1
        m = 0
        for r in range(Np):
            for k in range(K):
                if not mask[r, k]:
                    continue
                gi = group[r, k]
                B = num[gi] / den[gi] if den[gi] > 0.0 else 0.0
                out[q, m] = (B * c[m] - p[r, k]) * w[r, k]
                m += 1
    return out


@jit()
def _sample_buffers(S: int):
    """Output and scratch arrays of :func:`_line_samples_jacobian` for ``S`` samples per line."""
    return (
        np.empty(S), np.empty(S), np.empty(S), np.zeros((S, 6)), np.zeros((S, 6)), np.zeros((6, S)),
        np.empty(4), np.zeros((4, 6)), np.zeros(6), np.zeros(6), np.zeros(6), np.zeros(6), np.zeros(6), np.zeros(6), np.zeros(6), np.zeros(6),
    )


@jit(inline="always")
def _kinks_jacobian(t_s, tc, z0, vx, vz, R, exposure_s, focal_px, te, dte, dc, dA, dB, dAmB):
    """The blur's half-widths and the kinks' angles of one line (no acceleration), with their derivatives (:func:`_line_samples_jacobian`).

    Fills ``dA, dB, dAmB`` (6,) and the kinks' angles ``te`` (4,) with their
    derivatives ``dte`` (4, 6) (``dc`` is scratch); returns ``(dt0, x0, A,
    B, |A - B|, A + B)`` (s, m).
    """
    dt0 = t_s - tc
    x0 = vx * dt0
    z_line = z0 + vz * dt0
    # d dt0 = -e0; d x0 = vx d dt0 + dt0 e3; d z_line = e2 - vz e0 + dt0 e5
    A = abs(vx) * (exposure_s / 2.0)
    sgn_vx = 1.0 if vx > 0.0 else (-1.0 if vx < 0.0 else 0.0)
    dA[:] = 0.0
    dA[3] = sgn_vx * (exposure_s / 2.0)
    B = max(z_line, 0.0) / (2.0 * focal_px)
    dB[:] = 0.0
    if z_line > 0.0:
        dB[0] = -vz / (2.0 * focal_px)
        dB[2] = 1.0 / (2.0 * focal_px)
        dB[5] = dt0 / (2.0 * focal_px)
    AmB = abs(A - B)
    s_ab = 1.0 if A - B > 0.0 else (-1.0 if A - B < 0.0 else 0.0)
    for j in range(6):
        dAmB[j] = s_ab * (dA[j] - dB[j])
    ApB = A + B
    for k in range(4):
        if k == 0:
            ck = x0 - ApB
        elif k == 1:
            ck = x0 - AmB
        elif k == 2:
            ck = x0 + AmB
        else:
            ck = x0 + ApB
        # d x0
        dc[:] = 0.0
        dc[0] = -vx
        dc[3] = dt0
        for j in range(6):
            if k == 0:
                dc[j] -= dA[j] + dB[j]
            elif k == 1:
                dc[j] -= dAmB[j]
            elif k == 2:
                dc[j] += dAmB[j]
            else:
                dc[j] += dA[j] + dB[j]
        cl = min(max(ck, -R), R)
        te[k] = math.asin(cl / R)
        if -R < ck < R:
            inv = 1.0 / math.sqrt((R - ck) * (R + ck))
            for j in range(6):
                dte[k, j] = dc[j] * inv
        else:
            for j in range(6):
                dte[k, j] = 0.0
    return dt0, x0, A, B, AmB, ApB


@jit(inline="always")
def _density_branch(ApB, AmB, dist, inv4AB, plateau):
    """The blur density's branch at distance ``dist`` (m) from the centre (0: none, 1: ramp, 2: plateau) and its value (1/m)."""
    if not ApB > 0.0:
        return 0, 0.0
    if dist > AmB:
        if ApB - dist > 0.0:
            return 1, (ApB - dist) * inv4AB
        return 0, 0.0
    return 2, plateau


@jit(inline="always")
def _density_coefficients(branch, dens, s_dd, inv4AB, plateau, mAB):
    """The density's derivative as coefficients of ``d(A + B)``, ``d(A B)``, ``d dd`` and ``d max(A, B)`` on its branch."""
    c_ab = 0.0
    c_prod = 0.0
    c_dd = 0.0
    c_max = 0.0
    if branch == 1:
        c_ab = inv4AB
        # (not inv4AB squared: it overflows for A B below 1e-154)
        c_prod = -dens * inv4AB * 4.0
        c_dd = -s_dd * inv4AB
    elif branch == 2 and 2.0 * mAB > 1e-300:
        c_max = -plateau * plateau * 2.0
    return c_ab, c_prod, c_dd, c_max


@jit(inline="always")
def _pixel_and_gain(n, focal_px, principal_px, k1, k2):
    """Pixel of the normalised coordinate ``n`` and its derivative ``du / dn`` (pixels)."""
    if k1 == 0.0 and k2 == 0.0:
        return principal_px + focal_px * n, focal_px
    return project(n, focal_px, principal_px, k1, k2), focal_px * distortion_slope(n, k1, k2)


@jit()
def _line_samples_jacobian(t_s, th, R, exposure_s, focal_px, principal_px, k1, k2, g, gw, buf):
    """One line's chord samples (:func:`averaged_samples` with samples) and their derivatives, into ``buf``.

    ``buf`` (:func:`_sample_buffers`) receives ``lo, hi, wk`` (S,) and
    ``dlo, dhi`` (S, 6), ``dwk`` (6, S): their derivatives with respect to
    ``th = (t_c, y0, z0, vx, vy, vz)`` by forward-mode differentiation by
    hand (no acceleration); its other arrays are scratch.  Where a clip or
    a branch holds, the derivative is that of the branch taken.
    """
    lo, hi, wk, dlo, dhi, dwk, te, dte, dc, dA, dB, dAmB, dang, dhalf, dx0v, dmaxv = buf
    tc, y0, z0, vx, vy, vz = th[0], th[1], th[2], th[3], th[4], th[5]
    nn = g.shape[0]
    # ---- the line's samples and their derivatives (averaged_samples' loop)
    dt0, x0, A, B, AmB, ApB = _kinks_jacobian(t_s, tc, z0, vx, vz, R, exposure_s, focal_px, te, dte, dc, dA, dB, dAmB)
    mAB = max(A, B)
    plateau = 1.0 / max(2.0 * mAB, 1e-300)
    inv4AB = 1.0 / max(4.0 * A * B, 1e-300)
    inv_a1 = 1.0 / vx if vx != 0.0 else 0.0
    c_inva1 = -inv_a1 * inv_a1
    for j in range(6):
        dx0v[j] = 0.0
        dmaxv[j] = dA[j] if A >= B else dB[j]
    dx0v[0] = -vx
    dx0v[3] = dt0
    for q in range(3):
        half = (te[q + 1] - te[q]) / 2.0
        for j in range(6):
            dhalf[j] = (dte[q + 1, j] - dte[q, j]) / 2.0
        for i in range(nn):
            ang = te[q] + half * (1.0 + g[i])
            for j in range(6):
                dang[j] = dte[q, j] + dhalf[j] * (1.0 + g[i])
            d = R * math.sin(ang)
            rho = R * math.cos(ang)
            jac = rho * (half * gw[i])
            dd = d - x0
            dist = abs(dd)
            s_dd = 1.0 if dd > 0.0 else (-1.0 if dd < 0.0 else 0.0)
            branch, dens = _density_branch(ApB, AmB, dist, inv4AB, plateau)
            wgt = dens * jac
            lo_m = dd - B
            hi_m = dd + B
            u_mean = 0.5 * (max(-A, lo_m) + min(A, hi_m))
            dts = u_mean * inv_a1 + dt0
            xc = vx * dts
            yc = y0 + vy * dts
            zc = z0 + vz * dts
            zpos = zc > 0.0
            zz = zc if zpos else 1.0
            ok, s, ww, root, inv_den = _tangent_terms(xc, yc, zc, d, rho)
            a_ = yc * ww
            b_ = rho * root
            n_lo = (a_ - b_) * inv_den
            n_hi = (a_ + b_) * inv_den
            jj = q * nn + i
            lo[jj], fp_lo = _pixel_and_gain(n_lo, focal_px, principal_px, k1, k2)
            hi[jj], fp_hi = _pixel_and_gain(n_hi, focal_px, principal_px, k1, k2)
            wk[jj] = wgt if ok else 0.0
            # the branches taken, as coefficients (a branch-free loop over the parameters)
            okf = 1.0 if ok else 0.0
            c_ab, c_prod, c_dd, c_max = _density_coefficients(branch, dens, s_dd, inv4AB, plateau, mAB)
            sel_lo = 1.0 if -A >= lo_m else 0.0
            sel_hi = 1.0 if A <= hi_m else 0.0
            zf = 1.0 if zpos else 0.0
            inv_zz = 1.0 / zz
            inv2root = okf / (2.0 * root)
            dinv_c = -inv_den * inv_den * okf
            gwi = gw[i]
            # y0 and vy move only the chord's height yc (by 1 and by dts)
            dy_lo = okf * (ww - rho * yc / root) * inv_den
            dy_hi = okf * (ww + rho * yc / root) * inv_den
            dlo[jj, 1] = fp_lo * dy_lo
            dhi[jj, 1] = fp_hi * dy_hi
            dlo[jj, 4] = fp_lo * dy_lo * dts
            dhi[jj, 4] = fp_hi * dy_hi * dts
            dwk[1, jj] = 0.0
            dwk[4, jj] = 0.0
            # t_c, z0, vx, vz (unit seeds as constants: the compiler folds them)
            for j, e_t, e_z, e_x, e_v in ((0, 1.0, 0.0, 0.0, 0.0), (2, 0.0, 1.0, 0.0, 0.0), (3, 0.0, 0.0, 1.0, 0.0), (5, 0.0, 0.0, 0.0, 1.0)):
                d_d = rho * dang[j]
                d_rho = -d * dang[j]
                d_jac = gwi * (d_rho * half + rho * dhalf[j])
                d_dd = d_d - dx0v[j]
                d_dens = c_ab * (dA[j] + dB[j]) + c_prod * (dA[j] * B + A * dB[j]) + c_dd * d_dd + c_max * dmaxv[j]
                dwk[j, jj] = okf * (d_dens * jac + dens * d_jac)
                d_u = 0.5 * (sel_lo * (-dA[j]) + (1.0 - sel_lo) * (d_dd - dB[j]) + sel_hi * dA[j] + (1.0 - sel_hi) * (d_dd + dB[j]))
                d_dts = d_u * inv_a1 + u_mean * c_inva1 * e_x - e_t
                d_xc = dts * e_x + vx * d_dts
                d_yc = vy * d_dts
                d_zc = e_z + dts * e_v + vz * d_dts
                d_s = (d_xc - d_d) * inv_zz - s * zf * d_zc * inv_zz
                d_ww = d_zc + d_s * xc + s * d_xc
                d_den = 2.0 * (ww * d_ww - rho * d_rho)
                d_root = (2.0 * yc * d_yc + d_den) * inv2root
                d_inv = dinv_c * d_den
                d_a = d_yc * ww + yc * d_ww
                d_b = d_rho * root + rho * d_root
                dlo[jj, j] = fp_lo * ((d_a - d_b) * inv_den + (a_ - b_) * d_inv)
                dhi[jj, j] = fp_hi * ((d_a + d_b) * inv_den + (a_ + b_) * d_inv)


@jit()
def averaged_edges_jacobian(
    th: np.ndarray,
    t: np.ndarray,
    radius_m: float,
    exposure_s: float,
    focal_px: float,
    principal_px: float,
    k1: float,
    k2: float,
    g: np.ndarray,
    gw: np.ndarray,
):
    """The averaged silhouette's edges and area at lines ``t`` (N,) and their exact derivatives (no acceleration).

    ``left = sum(w lo) / sum(w)``, ``right = sum(w hi) / sum(w)``, ``area =
    sum(w (hi - lo))`` over the line's samples (:func:`averaged_samples`),
    differentiated through the samples (:func:`_line_samples_jacobian`).
    Where the ball is absent both edges sit at the centre's projection, as
    there.  Returns ``(left, right, area)`` (N,) and their derivatives
    ``(dl, dr, da)`` (N, 6) with respect to ``(t_c, y0, z0, vx, vy, vz)``.
    """
    N = t.shape[0]
    nn = g.shape[0]
    S = 3 * nn
    tc, y0, z0, vx, vy, vz = th[0], th[1], th[2], th[3], th[4], th[5]
    buf = _sample_buffers(S)
    lo, hi, wk, dlo, dhi, dwk = buf[:6]
    left = np.empty(N)
    right = np.empty(N)
    area = np.empty(N)
    dl = np.zeros((N, 6))
    dr = np.zeros((N, 6))
    da = np.zeros((N, 6))
    sl = np.empty(6)
    sh = np.empty(6)
    sm = np.empty(6)
    for n in range(N):
        _line_samples_jacobian(t[n], th, radius_m, exposure_s, focal_px, principal_px, k1, k2, g, gw, buf)
        mass = 0.0
        sum_lo = 0.0
        sum_hi = 0.0
        for j in range(6):
            sl[j] = 0.0
            sh[j] = 0.0
            sm[j] = 0.0
        for q in range(S):
            w = wk[q]
            mass += w
            sum_lo += w * lo[q]
            sum_hi += w * hi[q]
            for j in range(6):
                sm[j] += dwk[j, q]
                sl[j] += dwk[j, q] * lo[q] + w * dlo[q, j]
                sh[j] += dwk[j, q] * hi[q] + w * dhi[q, j]
        area[n] = sum_hi - sum_lo
        for j in range(6):
            da[n, j] = sh[j] - sl[j]
        if mass > 0.0:
            inv_m = 1.0 / mass
            left[n] = sum_lo * inv_m
            right[n] = sum_hi * inv_m
            for j in range(6):
                dl[n, j] = (sl[j] - left[n] * sm[j]) * inv_m
                dr[n, j] = (sh[j] - right[n] * sm[j]) * inv_m
        else:
            # absent: both edges at the centre's projection
            dt0 = t[n] - tc
            z_line = z0 + vz * dt0
            y_line = y0 + vy * dt0
            zz = z_line if z_line > 0.0 else 1.0
            nc = y_line / zz
            u_c = project(nc, focal_px, principal_px, k1, k2)
            fp = focal_px * distortion_slope(nc, k1, k2)
            zf = 1.0 if z_line > 0.0 else 0.0
            # d y_line = (-vy, 1, 0, 0, dt0, 0); d z_line = (-vz, 0, 1, 0, 0, dt0)
            dyl = (-vy, 1.0, 0.0, 0.0, dt0, 0.0)
            dzl = (-vz, 0.0, 1.0, 0.0, 0.0, dt0)
            left[n] = u_c
            right[n] = u_c
            for j in range(6):
                dn = (dyl[j] - nc * zf * dzl[j]) / zz
                dl[n, j] = fp * dn
                dr[n, j] = fp * dn
    return left, right, area, dl, dr, da


@jit(inline="always")
def _end_derivatives(lo, hi, wk, dlo, dhi, a0, span, dend):
    """The coverage derivatives ``dend`` (span, 6) of one row's pixels from its chord ends' motion (:func:`pixel_residuals_jacobian`).

    A row's grid starts at ``a0`` (pixels).
    """
    # an end moves the coverage of the pixel that holds it (a sample with
    # hi < lo covers nothing and moves nothing)
    dend[:, :] = 0.0
    for jj in range(lo.shape[0]):
        wj = wk[jj]
        if wj == 0.0 or hi[jj] < lo[jj]:
            continue
        tt = hi[jj] - a0
        if 0.0 <= tt < span:
            kk = int(math.floor(tt))
            for j in range(6):
                dend[kk, j] += wj * dhi[jj, j]
        tt = lo[jj] - a0
        if 0.0 <= tt < span:
            kk = int(math.floor(tt))
            for j in range(6):
                dend[kk, j] -= wj * dlo[jj, j]


@jit(inline="always")
def _weight_histograms(lo, hi, dwk, a0, span, hwd, hwfd):
    """The derivatives of :func:`ramp_histogram`'s cumulative histograms with respect to the samples' weights ``dwk`` (6, S), into ``hwd, hwfd``."""
    # the weights' part: the coverage with the weights' derivatives (y0
    # and vy leave the weights alone), four histograms in one pass
    hwd[:, :] = 0.0
    hwfd[:, :] = 0.0
    for jj in range(lo.shape[0]):
        lj = lo[jj]
        hj = hi[jj]
        if hj < lj:
            hj = lj
        for side in range(2):
            x = hj if side == 0 else lj
            sg = 1.0 if side == 0 else -1.0
            tt = x - a0
            if tt >= span:
                for j in (0, 2, 3, 5):
                    hwd[j, span + 1] += sg * dwk[j, jj]
            elif tt >= -1.0:
                fb = math.floor(tt)
                bi = int(fb) + 1
                fr = tt - fb
                for j in (0, 2, 3, 5):
                    hwd[j, bi] += sg * dwk[j, jj]
                    hwfd[j, bi] += sg * dwk[j, jj] * fr
    for j in (0, 2, 3, 5):
        for bb in range(span, -1, -1):
            hwd[j, bb] += hwd[j, bb + 1]


@jit()
def pixel_residuals_jacobian(
    th: np.ndarray,
    t: np.ndarray,
    radius_m: float,
    exposure_s: float,
    focal_px: float,
    principal_px: float,
    k1: float,
    k2: float,
    g: np.ndarray,
    gw: np.ndarray,
    cols: np.ndarray,
    mask: np.ndarray,
    shade: np.ndarray,
    w: np.ndarray,
    p: np.ndarray,
    group: np.ndarray,
    n_groups: int,
    n_out: int,
):
    """:func:`pixel_residuals` of one parameter set ``th`` (6,) and their exact derivatives (no acceleration).

    The same arithmetic as :func:`averaged_samples` (with samples) followed
    by :func:`pixel_residuals`, carried forward with the derivatives of
    every intermediate with respect to ``(t_c, y0, z0, vx, vy, vz)``
    (forward-mode differentiation by hand): the quadrature's kink angles,
    nodes and weights, each sample's chord ends, each pixel's coverage (an
    end moves the coverage of the pixel that holds it), the groups'
    least-squares brightness and the whitened residuals.  Where a clip or
    a branch holds, its derivative is that of the branch taken, as the
    finite differences of the same computation see it away from the kinks.
    ``t`` (Np,) are the fitted lines' times.  Returns ``(r (n_out,), J
    (n_out, 6))``.
    """
    Np, K = cols.shape
    nn = g.shape[0]
    S = 3 * nn
    R = radius_m
    tc, y0, z0, vx, vy, vz = th[0], th[1], th[2], th[3], th[4], th[5]
    buf = _sample_buffers(S)
    lo, hi, wk, dlo, dhi, dwk = buf[:6]
    base, span = _row_grids(cols, mask)
    hw = np.empty(span + 2)
    hwf = np.empty(span + 2)
    hwd = np.empty((6, span + 2))
    hwfd = np.empty((6, span + 2))
    dend = np.zeros((span, 6))
    c = np.empty(n_out)
    cd = np.empty((n_out, 6))
    num = np.zeros(n_groups)
    den_g = np.zeros(n_groups)
    dnum = np.zeros((n_groups, 6))
    dden = np.zeros((n_groups, 6))
    m = 0
    for r in range(Np):
        _line_samples_jacobian(t[r], th, R, exposure_s, focal_px, principal_px, k1, k2, g, gw, buf)
        # ---- the line's pixel coverage and its derivatives
        a0 = base[r] - 0.5
        okh = ramp_histogram(lo, hi, wk, a0, span, hw, hwf)
        _end_derivatives(lo, hi, wk, dlo, dhi, a0, span, dend)
        _weight_histograms(lo, hi, dwk, a0, span, hwd, hwfd)
        for k in range(K):
            if not mask[r, k]:
                continue
            kk = int(round(cols[r, k] - base[r]))
            cov = grid_coverage(hw, hwf, kk) if okh else np.nan
            sh = shade[r, k]
            ck = cov * sh
            c[m] = ck
            ws = w[r, k] * w[r, k]
            gi = group[r, k]
            num[gi] += ck * p[r, k] * ws
            den_g[gi] += ck * ck * ws
            for j in range(6):
                dck = (dend[kk, j] + hwd[j, kk + 2] + hwfd[j, kk + 1]) * sh if okh else np.nan
                cd[m, j] = dck
                dnum[gi, j] += dck * p[r, k] * ws
                dden[gi, j] += 2.0 * ck * dck * ws
            m += 1
    # ---- the groups' least-squares brightness (variable projection) and the residuals
    res = np.empty(n_out)
    jac_out = np.empty((n_out, 6))
    m = 0
    for r in range(Np):
        for k in range(K):
            if not mask[r, k]:
                continue
            gi = group[r, k]
            wr = w[r, k]
            if den_g[gi] > 0.0:
                Bg = num[gi] / den_g[gi]
                res[m] = (Bg * c[m] - p[r, k]) * wr
                for j in range(6):
                    dBg = (dnum[gi, j] - Bg * dden[gi, j]) / den_g[gi]
                    jac_out[m, j] = (dBg * c[m] + Bg * cd[m, j]) * wr
            else:
                res[m] = -p[r, k] * wr
                for j in range(6):
                    jac_out[m, j] = 0.0
            m += 1
    return res, jac_out


@jit()
def chord_edges(theta: np.ndarray, t: np.ndarray, radius_m: float, focal_px: float, principal_px: float, k1: float, k2: float, acc: np.ndarray):
    """The chord model's edges and their analytic derivatives (:func:`ballscan.model.averaged.chord_jacobian`).

    Returns ``(u (2, N), J (2, N, 6), ok (N,), x (N,), w (N,), tau (N,))``:
    left (row 0) and right (row 1) edges in pixels and their derivatives
    with respect to ``(t_c, y0, z0, vx, vy, vz)``, finite garbage where
    ``ok`` is False; the centre's offset ``x`` from the viewing plane and
    depth ``w`` (m) and ``tau = t - t_c`` (s) of each line.
    """
    tc, y0, z0, vx, vy, vz = theta[0], theta[1], theta[2], theta[3], theta[4], theta[5]
    ax, ay, az = acc[0], acc[1], acc[2]
    has_acc = ax != 0.0 or ay != 0.0 or az != 0.0
    R = radius_m
    N = t.shape[0]
    u = np.empty((2, N))
    J = np.empty((2, N, 6))
    ok = np.empty(N, dtype=np.bool_)
    xs = np.empty(N)
    ws = np.empty(N)
    taus = np.empty(N)
    for i in range(N):
        tau = t[i] - tc
        if has_acc:
            h2 = 0.5 * tau * tau
            x = vx * tau + ax * h2
            y = y0 + vy * tau + ay * h2
            w = z0 + vz * tau + az * h2
        else:
            x = vx * tau
            y = y0 + vy * tau
            w = z0 + vz * tau
        r2 = R * R - x * x
        D = w * w - r2
        disc = y * y + D
        good = (r2 > 0.0) and (w > 0.0) and (D > 0.0) and (disc > 0.0)
        if good:
            rho = math.sqrt(r2)
            s = math.sqrt(disc)
            inv_D = 1.0 / D
        else:
            rho = 1.0
            s = 1.0
            inv_D = 1.0
        ok[i] = good
        xs[i] = x
        ws[i] = w
        taus[i] = tau
        rho_s = rho / s
        for side in range(2):
            sg = -1.0 if side == 0 else 1.0
            n = (y * w + sg * (rho * s)) * inv_D
            dn_dy = (w + sg * (rho_s * y)) * inv_D
            dn_dw = (y + sg * (rho_s * w) - 2.0 * n * w) * inv_D
            dn_dx = (sg * (x * (rho_s - s / rho)) - 2.0 * n * x) * inv_D
            gain = focal_px * distortion_slope(n, k1, k2)
            gx = dn_dx * gain
            gy = dn_dy * gain
            gw = dn_dw * gain
            J[side, i, 0] = -(gx * (vx + ax * tau) + gy * (vy + ay * tau) + gw * (vz + az * tau))
            J[side, i, 1] = gy
            J[side, i, 2] = gw
            J[side, i, 3] = gx * tau
            J[side, i, 4] = gy * tau
            J[side, i, 5] = gw * tau
            u[side, i] = project(n, focal_px, principal_px, k1, k2)
    return u, J, ok, xs, ws, taus


@jit()
def coverage_grid(u_lo: np.ndarray, u_hi: np.ndarray, wgt: np.ndarray, idx: np.ndarray, base: np.ndarray, span: int) -> np.ndarray:
    """Averaged pixel coverage on unit grids (:func:`ballscan.model.pixels.pixel_coverage`).

    ``u_lo, u_hi, wgt`` (P, N, S) chord samples; line ``n``'s pixels are
    ``base[n] + idx[n]`` (pixel centres, ``idx`` (N, C) integers from 0 to
    ``span - 1``).  Returns (P, N, C): for each pixel the samples' weights
    times the overlap of ``[lo, hi]`` with ``[col - 1/2, col + 1/2]``,
    summed (:func:`ramp_histogram`); NaN on a line with a NaN sample.
    """
    P, N, _ = u_lo.shape
    C = idx.shape[1]
    out = np.empty((P, N, C))
    hw = np.empty(span + 2)
    hwf = np.empty(span + 2)
    for q in range(P):
        for n in range(N):
            ok = ramp_histogram(u_lo[q, n], u_hi[q, n], wgt[q, n], base[n] - 0.5, span, hw, hwf)
            for c in range(C):
                out[q, n, c] = grid_coverage(hw, hwf, idx[n, c]) if ok else np.nan
    return out


@jit()
def hybrid_rows(
    th: np.ndarray, t: np.ndarray, radius_m: float, exposure_s: float, focal_px: float, principal_px: float, k1: float,
    k2: float, g: np.ndarray, gw: np.ndarray, reach_max: float, fd_lines: np.ndarray, needed: np.ndarray,
    with_fd_lines: bool, with_needed: bool,
):
    """:func:`ballscan.model.averaged.hybrid_jacobian` with ``analytic`` and no acceleration, in one compiled call.

    The chord's derivatives (:func:`chord_edges`) on every line, the
    averaged model's exact ones (:func:`averaged_edges_jacobian`) on the
    lines where the section offsets reach beyond ``reach_max`` (m) or the
    chord has no edge, and on ``fd_lines`` (with ``with_fd_lines``), of
    those only the ``needed`` ones (with ``with_needed``).  Returns ``(dl,
    dr, da, fd)``: the derivatives (N, 6) and the lines of the averaged
    model's.
    """
    N = t.shape[0]
    _, J, ok, x0, z, _ = chord_edges(th, t, radius_m, focal_px, principal_px, k1, k2, np.zeros(3))
    dl = J[0]
    dr = J[1]
    da = dr - dl
    # the section offsets' half-widths: the exposure's and the pixel height's
    vxt = abs(th[3])
    half_exposure = exposure_s / 2.0
    two_f = 2.0 * focal_px
    fd = np.empty(N, dtype=np.bool_)
    n_fd = 0
    for i in range(N):
        zi = z[i]
        zp = 0.0 if zi < 0.0 else zi
        reach = abs(x0[i]) + vxt * half_exposure + zp / two_f
        f = (not ok[i]) or reach > reach_max
        if with_fd_lines:
            f = f or fd_lines[i]
        if with_needed:
            f = f and needed[i]
        fd[i] = f
        n_fd += f
    if n_fd == 0:
        return dl, dr, da, fd
    idx = np.flatnonzero(fd)
    _, _, _, fl, fr, fa = averaged_edges_jacobian(th, t[idx], radius_m, exposure_s, focal_px, principal_px, k1, k2, g, gw)
    for k in range(n_fd):
        i = idx[k]
        for j in range(6):
            dl[i, j] = fl[k, j]
            dr[i, j] = fr[k, j]
            da[i, j] = fa[k, j]
    return dl, dr, da, fd



def warm_up() -> None:
    """Load (or compile) this module's kernels now, on tiny inputs (see :func:`ballscan.pipeline.warmup.warm_up`)."""
    th = np.array([[0.0, 0.0, 3.0, 30.0, 0.0, 0.0]])
    t = np.zeros((1, 1))
    g = np.zeros(1)
    gw = np.full(1, 2.0)
    _, _, _, _, _, _, lo, hi, w = averaged_samples(th, t, 0.03, 1e-5, 3000.0, 0.0, 0.0, 0.0, np.zeros(3), g, gw, True, True, np.zeros(1), np.ones(1))
    averaged_samples(th, t, 0.03, 1e-5, 3000.0, 0.0, 0.0, 0.0, np.zeros(3), g, gw, True, True, np.zeros(2), np.full(2, 0.5))
    one = np.ones((1, 1))
    pixel_residuals(lo, hi, w, np.zeros((1, 1)), np.ones((1, 1), dtype=np.bool_), one, one, one, np.zeros((1, 1), dtype=np.int64), 1, 1)
    averaged_edges_jacobian(th[0].copy(), np.zeros(1), 0.03, 1e-5, 3000.0, 0.0, 0.0, 0.0, g, gw)
    pixel_residuals_jacobian(
        th[0].copy(), np.zeros(1), 0.03, 1e-5, 3000.0, 0.0, 0.0, 0.0, g, gw,
        np.zeros((1, 1)), np.ones((1, 1), dtype=np.bool_), one, one, one, np.zeros((1, 1), dtype=np.int64), 1, 1,
    )
    coverage_grid(lo, hi, w, np.zeros((1, 1), dtype=np.int64), np.zeros(1), 1)
    chord_edges(th[0], np.zeros(1), 0.03, 3000.0, 0.0, 0.0, 0.0, np.zeros(3))
    b1 = np.ones(1, dtype=np.bool_)
    hybrid_rows(th[0].copy(), np.zeros(1), 0.03, 1e-5, 3000.0, 0.0, 0.0, 0.0, g, gw, 0.024, b1, b1, True, True)
