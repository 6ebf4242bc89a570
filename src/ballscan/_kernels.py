"""Compiled kernels of the averaged silhouette (numba).

The fit, the shading pass and the bounds evaluate the averaged silhouette
(:func:`ballscan.solve.fit.averaged_model`) tens of times per ball on a few
thousand chord samples.  As numpy expressions that is some hundred array
operations per call, whose fixed cost (a few microseconds each) was most of
the time on a ball's hundred lines; one loop over the samples does the same
arithmetic in one call.  The mathematics is that of
:func:`ballscan.model.silhouette.silhouette` with ``model="averaged"`` (see its
Notes; :func:`ballscan.solve.fit._model_core` documents the layout), which the
tests compare it against.

Compiled on first use and cached on disk (``cache=True``, where numba finds
a writable location; else compiled in each process).
"""

from __future__ import annotations

import math

import numpy as np

from .compiled import as_arg, jit


@jit(inline="always")
def _project(n: float, principal: float, focal: float, k1: float, k2: float) -> float:
    """Pixel of a normalised sensor coordinate (the camera's radial distortion)."""
    if k1 == 0.0 and k2 == 0.0:
        return principal + focal * n
    n2 = n * n
    return principal + focal * (n * (1.0 + n2 * (k1 + k2 * n2)))


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
):
    """The averaged silhouette of parameter sets ``th`` (P, 6) at line times ``t`` (1 or P, N).

    Returns ``(left, right, presence, area, spread, valid, u_lo, u_hi,
    wgt)``: per line (P, N), and per sample (P, N, 3 * n_nodes) when
    ``want_samples`` (else arrays of size 0).  ``spread`` and ``valid``
    are computed only with ``full`` (else 0 and True).
    """
    P = th.shape[0]
    N = t.shape[1]
    nn = g.shape[0]
    S = 3 * nn
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
            A = abs(a1) * (exposure_s / 2.0)
            B = max(z_line, 0.0) / (2.0 * focal_px)
            AmB = abs(A - B)
            ApB = A + B
            if not want_samples and (x0 - ApB >= R or x0 + ApB <= -R):
                # the line misses the ball: every kink clips to the same pole,
                # every sample weighs 0 (the loop below gives these values)
                u_c = _project(y_line / (z_line if z_line > 0.0 else 1.0), principal_px, focal_px, k1, k2)
                left[p, n] = u_c
                right[p, n] = u_c
                area[p, n] = 0.0
                presence[p, n] = 0.0
                if full:
                    spread[p, n] = 0.0
                    valid[p, n] = z_line > 0.0
                continue
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
                    s = (xc - d) / (zc if zc > 0.0 else 1.0)
                    w = zc + s * xc
                    den = w * w - rho * rho
                    disc = yc * yc + den
                    ok = (w > rho) and (disc > 0.0)
                    j = q * nn + i
                    if ok:
                        root = math.sqrt(disc)
                        inv_den = 1.0 / den
                    else:
                        root = 1.0
                        inv_den = 0.0
                        if wgt > 0.0:
                            invalid = True
                    a_ = yc * w
                    b_ = rho * root
                    lo = _project((a_ - b_) * inv_den, principal_px, focal_px, k1, k2)
                    hi = _project((a_ + b_) * inv_den, principal_px, focal_px, k1, k2)
                    wk = wgt if ok else 0.0
                    ulo[j] = lo
                    uhi[j] = hi
                    wok[j] = wk
                    mass += wk
                    sum_lo += wk * lo
                    sum_hi += wk * hi
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
                u_c = _project(y_line / (z_line if z_line > 0.0 else 1.0), principal_px, focal_px, k1, k2)
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


@jit(inline="always")
def _ramp_histogram(lo: np.ndarray, hi: np.ndarray, w: np.ndarray, a0: float, span: int, hw: np.ndarray, hwf: np.ndarray) -> bool:
    """One line's chord samples as a histogram over a unit grid of ``span`` pixels from ``a0`` (pixels).

    The overlap of ``[lo, hi]`` with pixel ``k`` (``[a0 + k, a0 + k + 1]``)
    is ``ramp(hi - a) - ramp(lo - a)``, ``ramp = clip(., 0, 1)``; the sum
    of the ramps over the samples is, for all the grid's pixels at once, a
    histogram of the samples' ends by pixel (``hw``: weights, ``hwf``:
    weights times the fractional position) and its cumulative sum.  On
    return pixel ``k``'s coverage is ``hw[k + 2] + hwf[k + 1]`` (``hw``
    holds the sums over the bins from each bin up).  An infinite end lies
    beyond the grid; ``hi < lo`` covers nothing.  Returns False (the line's
    coverage undefined) where a sample is NaN.
    """
    hw[:] = 0.0
    hwf[:] = 0.0
    for j in range(lo.shape[0]):
        lj = lo[j]
        hj = hi[j]
        wj = w[j]
        if lj != lj or hj != hj or wj != wj:
            return False
        if hj < lj:
            hj = lj
        for side in range(2):
            x = hj if side == 0 else lj
            sw = wj if side == 0 else -wj
            t = x - a0
            if t >= span:
                # beyond the grid: every pixel's ramp at 1
                hw[span + 1] += sw
            elif t >= -1.0:
                b = math.floor(t)
                bi = int(b) + 1
                hw[bi] += sw
                hwf[bi] += sw * (t - b)
            # else before the grid: no pixel's ramp
    for b in range(span, -1, -1):
        hw[b] += hw[b + 1]
    return True


@jit(inline="always")
def _grid_coverage(hw: np.ndarray, hwf: np.ndarray, k: int) -> float:
    """Pixel ``k``'s coverage from :func:`_ramp_histogram` (exactly 0 where the two ramps of every sample cancel)."""
    cov = hw[k + 2] + hwf[k + 1]
    return 0.0 if abs(cov) < 1e-14 else cov


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
    """Whitened pixel residuals ``(B_g s cov - p) w`` of ``P`` parameter sets (:func:`ballscan.solve.fit._pixel_residuals`).

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
    # each row's pixels on a unit grid from its first column (_ramp_histogram)
    base, span = _row_grids(cols, mask)
    hw = np.empty(span + 2)
    hwf = np.empty(span + 2)
    for q in range(P):
        num[:] = 0.0
        den[:] = 0.0
        m = 0
        for r in range(Np):
            ok = _ramp_histogram(s_lo[q, r], s_hi[q, r], s_w[q, r], base[r] - 0.5, span, hw, hwf)
            for k in range(K):
                if not mask[r, k]:
                    continue
                cov = _grid_coverage(hw, hwf, int(round(cols[r, k] - base[r]))) if ok else np.nan
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
            # which branch of the density
            if not ApB > 0.0:
                branch = 0
                dens = 0.0
            elif dist > AmB:
                if ApB - dist > 0.0:
                    branch = 1
                    dens = (ApB - dist) * inv4AB
                else:
                    branch = 0
                    dens = 0.0
            else:
                branch = 2
                dens = plateau
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
            s = (xc - d) / zz
            ww = zc + s * xc
            den = ww * ww - rho * rho
            disc = yc * yc + den
            ok = (ww > rho) and (disc > 0.0)
            if ok:
                root = math.sqrt(disc)
                inv_den = 1.0 / den
            else:
                root = 1.0
                inv_den = 0.0
            a_ = yc * ww
            b_ = rho * root
            n_lo = (a_ - b_) * inv_den
            n_hi = (a_ + b_) * inv_den
            jj = q * nn + i
            if k1 == 0.0 and k2 == 0.0:
                lo[jj] = principal_px + focal_px * n_lo
                hi[jj] = principal_px + focal_px * n_hi
                fp_lo = focal_px
                fp_hi = focal_px
            else:
                n2 = n_lo * n_lo
                lo[jj] = principal_px + focal_px * (n_lo * (1.0 + n2 * (k1 + k2 * n2)))
                fp_lo = focal_px * (1.0 + n2 * (3.0 * k1 + 5.0 * k2 * n2))
                n2 = n_hi * n_hi
                hi[jj] = principal_px + focal_px * (n_hi * (1.0 + n2 * (k1 + k2 * n2)))
                fp_hi = focal_px * (1.0 + n2 * (3.0 * k1 + 5.0 * k2 * n2))
            wk[jj] = wgt if ok else 0.0
            # the branches taken, as coefficients (a branch-free loop over the parameters)
            okf = 1.0 if ok else 0.0
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
            u_c = _project(nc, principal_px, focal_px, k1, k2)
            n2 = nc * nc
            fp = focal_px * (1.0 + n2 * (3.0 * k1 + 5.0 * k2 * n2))
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
        okh = _ramp_histogram(lo, hi, wk, a0, span, hw, hwf)
        # an end moves the coverage of the pixel that holds it (a sample with
        # hi < lo covers nothing and moves nothing)
        dend[:, :] = 0.0
        for jj in range(S):
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
        # the weights' part: the coverage with the weights' derivatives (y0
        # and vy leave the weights alone), four histograms in one pass
        hwd[:, :] = 0.0
        hwfd[:, :] = 0.0
        for jj in range(S):
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
        for k in range(K):
            if not mask[r, k]:
                continue
            kk = int(round(cols[r, k] - base[r]))
            cov = _grid_coverage(hw, hwf, kk) if okh else np.nan
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
    """The chord model's edges and their analytic derivatives (:func:`ballscan.solve.fit.chord_jacobian`).

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
            n2 = n * n
            gain = focal_px * (1.0 + n2 * (3.0 * k1 + 5.0 * k2 * n2))
            gx = dn_dx * gain
            gy = dn_dy * gain
            gw = dn_dw * gain
            J[side, i, 0] = -(gx * (vx + ax * tau) + gy * (vy + ay * tau) + gw * (vz + az * tau))
            J[side, i, 1] = gy
            J[side, i, 2] = gw
            J[side, i, 3] = gx * tau
            J[side, i, 4] = gy * tau
            J[side, i, 5] = gw * tau
            u[side, i] = _project(n, principal_px, focal_px, k1, k2)
    return u, J, ok, xs, ws, taus


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
            h = hs[j]
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
                a = max(math.sqrt(nx * nx + ny * ny + nz * nz), 1e-12)
                a = 1.0 / a
                lam = nx * a * light[0] + ny * a * light[1] + nz * a * light[2]
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


@jit()
def coverage_grid(u_lo: np.ndarray, u_hi: np.ndarray, wgt: np.ndarray, idx: np.ndarray, base: np.ndarray, span: int) -> np.ndarray:
    """Averaged pixel coverage on unit grids (:func:`ballscan.solve.fit.pixel_coverage`).

    ``u_lo, u_hi, wgt`` (P, N, S) chord samples; line ``n``'s pixels are
    ``base[n] + idx[n]`` (pixel centres, ``idx`` (N, C) integers from 0 to
    ``span - 1``).  Returns (P, N, C): for each pixel the samples' weights
    times the overlap of ``[lo, hi]`` with ``[col - 1/2, col + 1/2]``,
    summed (:func:`_ramp_histogram`); NaN on a line with a NaN sample.
    """
    P, N, _ = u_lo.shape
    C = idx.shape[1]
    out = np.empty((P, N, C))
    hw = np.empty(span + 2)
    hwf = np.empty(span + 2)
    for q in range(P):
        for n in range(N):
            ok = _ramp_histogram(u_lo[q, n], u_hi[q, n], wgt[q, n], base[n] - 0.5, span, hw, hwf)
            for c in range(C):
                out[q, n, c] = _grid_coverage(hw, hwf, idx[n, c]) if ok else np.nan
    return out


@jit()
def fit_residuals(
    left: np.ndarray, right: np.ndarray, area: np.ndarray, il: np.ndarray, ir: np.ndarray, ia: np.ndarray, b: float,
    ml: np.ndarray, mr: np.ndarray, ma: np.ndarray, sl: np.ndarray, sr: np.ndarray, sa: np.ndarray, tail: np.ndarray,
) -> np.ndarray:
    """The fit's whitened residuals (:func:`ballscan.solve.fit.fit_motion`): selected edges and areas, then ``tail``.

    ``(left[il] - b - ml) / sl``, ``(right[ir] + b - mr) / sr``, ``(area[ia]
    - ma) / sa`` and ``tail`` (the pixel residuals) in one array, the same
    operations as the numpy expressions.
    """
    nl, nr, na = il.shape[0], ir.shape[0], ia.shape[0]
    r = np.empty(nl + nr + na + tail.shape[0])
    for k in range(nl):
        r[k] = (left[il[k]] - b - ml[k]) / sl[k]
    o = nl
    for k in range(nr):
        r[o + k] = (right[ir[k]] + b - mr[k]) / sr[k]
    o += nr
    for k in range(na):
        r[o + k] = (area[ia[k]] - ma[k]) / sa[k]
    o += na
    for k in range(tail.shape[0]):
        r[o + k] = tail[k]
    return r


@jit()
def fit_jacobian(
    dl: np.ndarray, dr: np.ndarray, da: np.ndarray, il: np.ndarray, ir: np.ndarray, ia: np.ndarray,
    sl: np.ndarray, sr: np.ndarray, sa: np.ndarray, tail: np.ndarray, with_bias: bool,
) -> np.ndarray:
    """The fit's whitened Jacobian (:func:`ballscan.solve.fit.fit_motion`) from per-line derivatives (N, 6).

    Rows ``dl[il] / sl``, ``dr[ir] / sr``, ``da[ia] / sa``, then ``tail``
    (M, 6) (the pixel residuals'); with ``with_bias`` a seventh column, the
    edge bias's ``-1 / sl``, ``1 / sr`` and 0.
    """
    nl, nr, na, nt = il.shape[0], ir.shape[0], ia.shape[0], tail.shape[0]
    J = np.empty((nl + nr + na + nt, 7 if with_bias else 6))
    for k in range(nl):
        for j in range(6):
            J[k, j] = dl[il[k], j] / sl[k]
    o = nl
    for k in range(nr):
        for j in range(6):
            J[o + k, j] = dr[ir[k], j] / sr[k]
    o += nr
    for k in range(na):
        for j in range(6):
            J[o + k, j] = da[ia[k], j] / sa[k]
    o += na
    for k in range(nt):
        for j in range(6):
            J[o + k, j] = tail[k, j]
    if with_bias:
        for k in range(nl):
            J[k, 6] = -1.0 / sl[k]
        for k in range(nr):
            J[nl + k, 6] = 1.0 / sr[k]
        for k in range(nl + nr, J.shape[0]):
            J[k, 6] = 0.0
    return J


@jit()
def block_ratio(r: np.ndarray, sizes) -> float:
    """The largest significant block-mean variance ratio of one side's residuals (:func:`ballscan.solve.fit._block_scale`), else 1.

    numpy's sums (:func:`_pairwise_sum`) for the block means and their mean
    square, so that the ratios are those of the numpy expressions.
    """
    best = 1.0
    for B in sizes:
        nb = r.shape[0] // B
        if nb < 4:
            continue
        m2 = np.empty(nb)
        for i in range(nb):
            m = _pairwise_sum(r[i * B : (i + 1) * B]) / B
            m2[i] = m * m
        ratio = B * (_pairwise_sum(m2) / nb)
        if ratio > 1.0 + 3.0 * math.sqrt(2.0 / nb):
            best = max(best, ratio)
    return best


@jit()
def area_tables(
    area: np.ndarray, area_sigma: np.ndarray, level: np.ndarray, level_sigma: np.ndarray, floor2: float, floor_px2: float
):
    """The fit's levelled areas, their 1-sigma and where they exist (:func:`ballscan.solve.fit._area_tables`), per line.

    The numpy form's operations, line by line: a NaN ``level_sigma`` counts
    as infinite and an infinite one as the largest float (``np.nan_to_num``
    with ``nan=inf``).
    """
    n = area.shape[0]
    ma = np.empty(n)
    sa = np.empty(n)
    ok = np.empty(n, dtype=np.bool_)
    big = np.finfo(np.float64).max
    for i in range(n):
        rel = level_sigma[i]
        if math.isnan(rel):
            rel = math.inf
        elif math.isinf(rel):
            rel = big if rel > 0.0 else -big
        lev = level[i]
        good = math.isfinite(lev) and lev > 0.05 and math.isfinite(rel)
        ls = lev if good else 1.0
        m = area[i] / ls if good else 0.0
        r = rel if good else 0.0
        rel2 = r * r + floor2
        q = area_sigma[i] / ls
        mp = 0.0 if m < 0.0 else m
        ma[i] = m
        sa[i] = math.sqrt(q * q + rel2 * (mp * mp) + floor_px2) if good else math.inf
        ok[i] = good
    return ma, sa, ok


@jit()
def select_lines(
    presence: np.ndarray, valid: np.ndarray, spread: np.ndarray, left_ok: np.ndarray, right_ok: np.ndarray,
    left: np.ndarray, right: np.ndarray, end_line: np.ndarray, wide: bool, left_wide_ok: np.ndarray,
    right_wide_ok: np.ndarray, left_wide: np.ndarray, right_wide: np.ndarray, max_spread: float, max_spread_wide: float,
    end_line_areas: bool,
):
    """The fit's residual selection (:func:`ballscan.solve.fit._select`), line by line.

    Returns the masks ``(use_l, use_r, use_a, wide_l, wide_r)``; the wide
    window's arrays are read only with ``wide``.
    """
    n = presence.shape[0]
    use_l = np.empty(n, dtype=np.bool_)
    use_r = np.empty(n, dtype=np.bool_)
    use_a = np.empty(n, dtype=np.bool_)
    wide_l = np.zeros(n, dtype=np.bool_)
    wide_r = np.zeros(n, dtype=np.bool_)
    for i in range(n):
        full = presence[i] > 0.999 and valid[i]
        narrow = full and spread[i] <= max_spread
        ul = left_ok[i] and narrow and math.isfinite(left[i])
        ur = right_ok[i] and narrow and math.isfinite(right[i])
        if wide:
            between = full and spread[i] > max_spread and spread[i] <= max_spread_wide
            wide_l[i] = left_wide_ok[i] and between and math.isfinite(left_wide[i])
            wide_r[i] = right_wide_ok[i] and between and math.isfinite(right_wide[i])
            ul = ul or wide_l[i]
            ur = ur or wide_r[i]
        # no signal: neither edge measured nor an end line
        no_signal = not (left_ok[i] or right_ok[i] or end_line[i])
        if end_line_areas:
            ua = not (ul or ur) and (end_line[i] or no_signal or (left_ok[i] and right_ok[i]))
        else:
            ua = not (ul or ur) and no_signal
        use_l[i] = ul
        use_r[i] = ur
        use_a[i] = ua
    return use_l, use_r, use_a, wide_l, wide_r


@jit()
def hybrid_rows(
    th: np.ndarray, t: np.ndarray, radius_m: float, exposure_s: float, focal_px: float, principal_px: float, k1: float,
    k2: float, g: np.ndarray, gw: np.ndarray, reach_max: float, fd_lines: np.ndarray, needed: np.ndarray,
    with_fd_lines: bool, with_needed: bool,
):
    """:func:`ballscan.solve.fit.hybrid_jacobian` with ``analytic`` and no acceleration, in one compiled call.

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


@jit()
def equilibrated(AJ: np.ndarray):
    """Column norms ``cn = sqrt(diag(AJ))`` (1 where not positive) of a normal matrix and ``AJ / outer(cn, cn)``.

    The Levenberg-Marquardt steps' equilibration (:func:`ballscan.solve.fit._levenberg_marquardt`),
    the numpy expressions' operations.
    """
    n = AJ.shape[0]
    cn = np.empty(n)
    for i in range(n):
        c = math.sqrt(AJ[i, i])
        cn[i] = c if c > 0.0 else 1.0
    A = np.empty((n, n))
    for i in range(n):
        for j in range(n):
            A[i, j] = AJ[i, j] / (cn[i] * cn[j])
    return cn, A


@jit()
def damped(A: np.ndarray, lam: float) -> np.ndarray:
    """``A + lam * diag(diag(A))`` (the numpy expression's operations: ``+ lam * 0`` off the diagonal)."""
    n = A.shape[0]
    out = np.empty((n, n))
    for i in range(n):
        for j in range(n):
            d = A[i, i] if i == j else 0.0
            out[i, j] = A[i, j] + lam * d
    return out


@jit()
def on_both_sides(lines: np.ndarray, t: np.ndarray, t_c: float) -> bool:
    """Whether the mask ``lines`` holds lines both before and after ``t_c`` (line times ``t``).

    :func:`ballscan.solve.fit._at_both_ends` in one pass.
    """
    before = False
    after = False
    for i in range(lines.shape[0]):
        if lines[i]:
            before = before or t[i] < t_c
            after = after or t[i] > t_c
    return before and after


@jit()
def loose_rows(
    J: np.ndarray, r: np.ndarray, rows: np.ndarray, sa: np.ndarray, sa_loose: np.ndarray, model: np.ndarray, ma_loose: np.ndarray
):
    """The partial lines' rows made loose and both Jacobians equilibrated (:func:`ballscan.solve.fit._partial_verdict`).

    ``J`` (M, p) and ``r`` (M,) are the levelled fit's whitened Jacobian and
    residuals, ``rows`` the partial lines' rows in them, ``sa`` their
    levelled sigmas, ``sa_loose`` and ``ma_loose`` their loose sigmas and
    areas, ``model`` the model's areas there.  Returns ``(r_l, Jl_n, Jt_n,
    gn)``: the loose residuals, both Jacobians divided by the loose one's
    column norms (1 where 0; summed row by row as numpy's ``norm(axis=0)``)
    and the model's area derivatives on those rows, divided too.
    """
    M, p = J.shape
    n = rows.shape[0]
    J_l = J.copy()
    r_l = r.copy()
    g = np.empty((n, p))
    for k in range(n):
        i = rows[k]
        for j in range(p):
            g[k, j] = J[i, j] * sa[k]
            J_l[i, j] = g[k, j] / sa_loose[k]
        r_l[i] = (model[k] - ma_loose[k]) / sa_loose[k]
    cn = np.zeros(p)
    for i in range(M):
        for j in range(p):
            cn[j] += J_l[i, j] * J_l[i, j]
    for j in range(p):
        c = math.sqrt(cn[j])
        cn[j] = c if c > 0.0 else 1.0
    Jl_n = np.empty((M, p))
    Jt_n = np.empty((M, p))
    for i in range(M):
        for j in range(p):
            Jl_n[i, j] = J_l[i, j] / cn[j]
            Jt_n[i, j] = J[i, j] / cn[j]
    gn = np.empty((n, p))
    for k in range(n):
        for j in range(p):
            gn[k, j] = g[k, j] / cn[j]
    return r_l, Jl_n, Jt_n, gn


def warm_up() -> None:
    """Load (or compile) every kernel now, on tiny inputs.

    The first call in a process otherwise carries it (about 0.2 s from the
    on-disk cache, seconds to compile): a stream calls this before its
    first ball so that the ball's latency does not.
    """
    th = np.array([[0.0, 0.0, 3.0, 30.0, 0.0, 0.0]])
    t = np.zeros((1, 1))
    g = np.zeros(1)
    gw = np.full(1, 2.0)
    _, _, _, _, _, _, lo, hi, w = averaged_samples(th, t, 0.03, 1e-5, 3000.0, 0.0, 0.0, 0.0, np.zeros(3), g, gw, True, True)
    one = np.ones((1, 1))
    pixel_residuals(lo, hi, w, np.zeros((1, 1)), np.ones((1, 1), dtype=np.bool_), one, one, one, np.zeros((1, 1), dtype=np.int64), 1, 1)
    averaged_edges_jacobian(th[0].copy(), np.zeros(1), 0.03, 1e-5, 3000.0, 0.0, 0.0, 0.0, g, gw)
    pixel_residuals_jacobian(
        th[0].copy(), np.zeros(1), 0.03, 1e-5, 3000.0, 0.0, 0.0, 0.0, g, gw,
        np.zeros((1, 1)), np.ones((1, 1), dtype=np.bool_), one, one, one, np.zeros((1, 1), dtype=np.int64), 1, 1,
    )
    coverage_grid(lo, hi, w, np.zeros((1, 1), dtype=np.int64), np.zeros(1), 1)
    chord_edges(th[0], np.zeros(1), 0.03, 3000.0, 0.0, 0.0, 0.0, np.zeros(3))
    # the fit's residuals and Jacobian from its selection
    i1, o1, d6 = np.zeros(1, dtype=np.int64), np.ones(1), np.zeros((1, 6))
    fit_residuals(o1, o1, o1, i1, i1, i1, 0.0, o1, o1, o1, o1, o1, o1, np.zeros(0))
    fit_jacobian(d6, d6, d6, i1, i1, i1, o1, o1, o1, np.zeros((0, 6)), True)
    block_ratio(np.zeros(16), (4, 8, 16))
    area_tables(o1, o1, o1, o1, 0.0, 0.0)
    b1 = np.ones(1, dtype=np.bool_)
    select_lines(o1, b1, o1, b1, b1, o1, o1, b1, True, b1, b1, o1, o1, 0.3, 0.8, True)
    hybrid_rows(th[0].copy(), np.zeros(1), 0.03, 1e-5, 3000.0, 0.0, 0.0, 0.0, g, gw, 0.024, b1, b1, True, True)
    damped(equilibrated(np.eye(2))[1], 1e-3)
    on_both_sides(b1, o1, 0.0)
    loose_rows(d6, o1, i1, o1, o1, o1, o1)
    limb_values(
        np.zeros(1), np.zeros((1, 1)), np.zeros((1, 1)), np.ones(1, dtype=np.bool_), np.zeros(1), np.zeros(1),
        3000.0, th[0, :3].copy(), th[0, 3:].copy(), np.zeros(3), 0.0, 0.03, np.ones(3), 0.0, 1.0,
    )
    # the detection's and the edges' loops (section at the end of the module)
    mode_seek(np.zeros((1, 2), dtype=np.float32), np.zeros(1), np.ones(1), 0.5)
    one32 = np.ones(2, dtype=np.float32)
    label_hits(np.ones((2, 2), dtype=np.float32), one32, one32, one32, one32)
    integer_median_mad(np.zeros(2, dtype=np.float32))
    reflect_median_filter(np.zeros(3), 3)
    s, e = first_pass_lines(np.ones((1, 2), dtype=np.float32), np.ones(1), np.zeros(1), np.ones(2), np.ones(2), True)
    kept_median(s, e, 1e300)
    multi_runs(group_mask(np.zeros((2, 2), dtype=np.int32), 0, 2, 0, 2, np.ones(1, dtype=np.bool_)), 1)
    region_values(np.ones((2, 2)), np.ones(2), np.ones(2), np.zeros(2), 0, 0, fill_lines_and_cols(np.ones((2, 2), dtype=np.bool_)), 255.0)
    prof = np.zeros((1, 8))
    k0 = np.zeros(1, dtype=np.int64)
    k1 = np.full(1, 7, dtype=np.int64)
    yes = np.ones(1, dtype=np.bool_)
    walk_edges(prof, k0, k1, yes, np.zeros(1), 0.25, 1)
    inner_differences(prof, prof, k0, k1, yes)
    flags = np.zeros((1, 8), dtype=np.bool_)
    edge_windows(prof, prof, flags, flags, k0, k1, k0, k0, 1)
    # the limb levels, the shading fit, the line levels and their scatter (sections at the end of the module)
    z1 = np.zeros(1)
    limb_levels(
        np.ones(1), np.zeros((1, 3)), np.ones(1, dtype=np.int64), 1, 1, z1, z1, z1, z1, np.ones(1), z1, np.zeros((1, 1)), z1, z1, 1,
        np.zeros((1, 1)), np.ones((1, 1)), np.ones((1, 1)), z1, z1, yes, k0, np.zeros((1, 1)), z1, z1,
        3000.0, 0.0, 0.0, 0.0, th[0, :3].copy(), th[0, 3:].copy(), np.zeros(3), 0.0, 0.03, np.ones(3), 0.0, 1.0,
    )
    shading_fit(np.arange(8.0), np.tile(np.array([0.6, 0.0, -0.8]), (8, 1)), 1.5, 1, 1.5, 0.01)
    law = (3000.0, 0.0, 0.0, 0.0, th[0, :3].copy(), th[0, 3:].copy(), np.zeros(3), 0.0, 0.03, np.ones(3), 0.0, 1.0)
    line_level_sums(np.zeros((1, 1)), np.ones((1, 1), dtype=np.bool_), z1, z1, yes, k0, np.zeros((1, 1)), z1, z1, *law)
    interior_normals(z1, k0, k0, np.zeros((0, 0), dtype=np.bool_), 0, 0, *law[:4], *law[4:9])
    level_scatter(k0, k0, np.ones(1, dtype=np.int64), k0, np.ones((1, 1)), np.ones((1, 1)), 0, z1, z1, np.zeros((1, 1)), z1, z1, *law)
    # the column gains' medians and the edges' whole-box and per-row passes (sections at the end of the module)
    sorted_medians(np.zeros((1, 1)), np.ones((1, 1), dtype=np.bool_), 0)
    median_deviations(np.zeros((1, 1)), np.ones((1, 1), dtype=np.bool_))
    rough_edges(prof, np.ones(1), 0.25)
    shot_noise(prof, prof, 1.0, 1.0)
    line_coverage(prof, prof, k0, k1, yes, 0)
    rows4 = np.ones(4)
    flags4 = np.ones(4, dtype=np.bool_)
    ints4 = np.ones(4, dtype=np.int64)
    running_medians(rows4, 4, 3)
    level_gradients(rows4, rows4, rows4, rows4, rows4, rows4, rows4, rows4, flags4, np.zeros(2, dtype=np.int64), 2, 9)
    shaded_sides(rows4, rows4, flags4, 4, 2.0)
    window_edges(rows4, rows4, rows4, rows4, rows4, rows4, ints4, ints4, ints4, ints4, 1.0, 1.0)
    finished_edges(rows4, rows4, rows4, rows4, ints4, rows4, flags4, rows4, flags4, yes, yes, 0)
    limb_pixels(k0, ints4, ints4, ints4, ints4, np.zeros((4, 2), dtype=np.int64), np.zeros((4, 2), dtype=np.int64))
    finite_rows(prof)
    chord_rows(np.zeros((1, 2)), np.zeros((1, 2)), np.ones((1, 2)), z1, z1, k0, np.ones(1))
    unique_lines(k0)
    level_spans(z1, z1, z1, 2)
    warm_up_stream()


# ---------------------------------------------------------------------------
# Detection and edge measurement: compiled loops of a ball's crop
# ---------------------------------------------------------------------------
# A stream measures each ball on a crop of about 150 x 200 pixels, within a
# latency budget of 10 ms (benchmarks/bench_stream.py).  On arrays that small
# the numpy versions of these loops spent most of their time in the fixed
# cost of some hundred whole-array operations (the mode seeking of the
# detector's background 0.75 ms per crop, its masked line medians 0.25 ms,
# the edges' running medians 0.3 ms); one pass over the data does the same.


@jit()
def _search_keys(s: np.ndarray, i: int, shift: float, x: float, right: bool) -> int:
    """Number of ``float64(s[i, j]) - shift`` (ascending in ``j``) below ``x`` (``right``: at most ``x``)."""
    lo = 0
    hi = s.shape[1]
    while lo < hi:
        mid = (lo + hi) // 2
        key = np.float64(s[i, mid]) - shift
        if key < x or (right and key == x):
            lo = mid + 1
        else:
            hi = mid
    return lo


@jit()
def _window_spread(s: np.ndarray, i: int, m: float, half: float):
    """Spread, count and mean offset of the values of row ``i`` of ``s`` within ``half`` of ``m``.

    In ``s``'s float32 like :func:`ballscan.measure.detection._mode_seek`'s numpy
    form (offsets ``s - m`` and the window test in float32), the sums in
    float64 (one running sum, where numpy sums pairwise: the same to
    round-off).
    """
    m32 = np.float32(m)
    h32 = np.float32(half)
    k = 0
    t1 = 0.0
    t2 = 0.0
    for j in range(s.shape[1]):
        d = s[i, j] - m32
        if abs(d) <= h32:
            k += 1
            dd = np.float64(d)
            t1 += dd
            t2 += dd * dd
    kk = max(k, 1)
    mean = t1 / kk
    var = t2 / kk - mean * mean
    return math.sqrt(max(var, 0.0) * kk / max(kk - 1, 1)), k, mean


@jit()
def mode_seek(s: np.ndarray, start: np.ndarray, sigma: np.ndarray, floor: float):
    """Mode, noise sigma and final window count of each row of the row-sorted float32 ``s`` (:func:`ballscan.measure.detection._mode_seek`).

    The windows are found as there, by a search among the keys
    ``s - (s[:, 0] - row * span)`` (``span`` one more than the largest
    row's range), here row by row on the same float64 keys, so the windows
    and medians are those of the numpy form; the window means and spreads
    agree to round-off (summation order).
    """
    w, n = s.shape
    centre = np.empty(w)
    sig_out = np.empty(w)
    cnt = np.zeros(w, dtype=np.int64)
    if w == 0 or n == 0:
        return centre, sig_out, cnt
    span = -np.inf
    for i in range(w):
        span = max(span, np.float64(s[i, n - 1]) - np.float64(s[i, 0]))
    span += 1.0
    for i in range(w):
        base = np.float64(s[i, 0])
        top = (np.float64(s[i, n - 1]) - base) + 0.25
        row_shift = i * span
        shift = base - row_shift
        m = start[i]
        sg = max(sigma[i], floor)
        c = 0
        for it in range(4):
            if it == 2:
                sd, k, _ = _window_spread(s, i, m, 4.5 * sg)
                # the spread of a window of fewer than ~8 values is meaningless
                if k >= 8:
                    sg = max(sd, floor)
            half = 4.5 * sg
            lo = min(max(m - half - base, -0.25), top) + row_shift
            hi = min(max(m + half - base, -0.25), top) + row_shift
            a = _search_keys(s, i, shift, lo, False)
            c = _search_keys(s, i, shift, hi, True) - a
            if c >= 1:
                i0 = min(max(a + (c - 1) // 2, 0), n - 1)
                i1 = min(max(a + c // 2, 0), n - 1)
                m = 0.5 * (np.float64(s[i, i0]) + np.float64(s[i, i1]))
        sd, k, mean = _window_spread(s, i, m, 4.5 * sg)
        if k >= 8:
            sg = max(sd, floor)
        # the window's mean, not its median (a median of integer data is an integer)
        if k >= 1:
            m = m + mean
        centre[i] = m
        sig_out[i] = sg
        cnt[i] = c
    return centre, sig_out, cnt


@jit(inline="always")
def _root(parent: np.ndarray, q: int) -> int:
    """Root of ``q`` in the union-find forest ``parent`` (path halving)."""
    while parent[q] != q:
        parent[q] = parent[parent[q]]
        q = parent[q]
    return q


@jit(inline="always")
def _grown(a: np.ndarray, size: int) -> np.ndarray:
    """A copy of the 1-D ``a`` with room for ``size`` entries."""
    out = np.empty(size, dtype=a.dtype)
    out[: a.size] = a
    return out


@jit()
def label_hits(x: np.ndarray, gain: np.ndarray, b: np.ndarray, offset: np.ndarray, thr: np.ndarray):
    """8-connected labels, sizes and boxes of the pixels with ``|x - (gain b + offset)| > thr`` (:func:`ballscan.measure.detection.detect`).

    The test is in float32 like the numpy form (``x``, ``gain``, ``b``,
    ``offset`` and ``thr`` float32).  The labels are numbered as
    ``scipy.ndimage.label`` (structure ``ones((3, 3))``) numbers them, in
    the raster order of each component's first pixel, so ``lab`` (int32)
    is its array; ``sizes[k]`` and ``boxes[k] = (line_start, line_stop,
    col_start, col_stop)`` belong to label ``k + 1`` (``np.bincount`` and
    ``ndi.find_objects`` of it).  Runs of hit pixels along each line are
    joined (union-find) with the runs of the line above that touch them.
    """
    n, w = x.shape
    lab = np.zeros((n, w), dtype=np.int32)
    # room for the runs, doubled when a line might not fit (a line holds at
    # most (w + 1) // 2; all lines that many would be a large image's
    # memory many times over)
    per_line = (w + 1) // 2
    cap = 4 * n + per_line
    run_line = np.empty(cap, dtype=np.int64)
    run_start = np.empty(cap, dtype=np.int64)
    run_stop = np.empty(cap, dtype=np.int64)
    parent = np.empty(cap, dtype=np.int64)
    row = np.empty(w, dtype=np.bool_)
    n_run = 0
    prev_first = 0  # the runs of the line above: [prev_first, first)
    for i in range(n):
        first = n_run
        if n_run + per_line > cap:
            cap = 2 * cap + per_line
            run_line = _grown(run_line, cap)
            run_start = _grown(run_start, cap)
            run_stop = _grown(run_stop, cap)
            parent = _grown(parent, cap)
        g = gain[i]
        o = offset[i]
        # the test first, over the whole line (a loop without branches)
        for j in range(w):
            row[j] = abs(x[i, j] - (g * b[j] + o)) > thr[j]
        j = 0
        while j < w:
            if not row[j]:
                j += 1
                continue
            start = j
            j += 1
            while j < w and row[j]:
                j += 1
            run_line[n_run] = i
            run_start[n_run] = start
            run_stop[n_run] = j
            parent[n_run] = n_run
            n_run += 1
        # 8-connected: runs [a, b) and [c, d) of neighbouring lines touch where a <= d and c <= b
        q = prev_first
        for r in range(first, n_run):
            while q < first and run_stop[q] < run_start[r]:
                q += 1
            k = q
            while k < first and run_start[k] <= run_stop[r]:
                ra = _root(parent, r)
                rb = _root(parent, k)
                if ra < rb:
                    parent[rb] = ra
                elif rb < ra:
                    parent[ra] = rb
                k += 1
        prev_first = first
    final = np.zeros(n_run, dtype=np.int32)
    sizes = np.zeros(n_run, dtype=np.int64)
    boxes = np.empty((n_run, 4), dtype=np.int64)
    n_lab = 0
    for r in range(n_run):
        root = _root(parent, r)
        k = final[root]
        if k == 0:
            n_lab += 1
            k = n_lab
            final[root] = k
            boxes[k - 1, 0] = run_line[r]
            boxes[k - 1, 2] = run_start[r]
            boxes[k - 1, 3] = run_stop[r]
        i = run_line[r]
        for j in range(run_start[r], run_stop[r]):
            lab[i, j] = k
        sizes[k - 1] += run_stop[r] - run_start[r]
        boxes[k - 1, 1] = i + 1
        boxes[k - 1, 2] = min(boxes[k - 1, 2], run_start[r])
        boxes[k - 1, 3] = max(boxes[k - 1, 3], run_stop[r])
    return lab, sizes[:n_lab].copy(), boxes[:n_lab].copy()


@jit(inline="always")
def _rank_in_counts(counts: np.ndarray, k: int) -> int:
    """Index of the value of rank ``k`` (0-based) in the histogram ``counts``."""
    seen = 0
    for i in range(counts.size):
        seen += counts[i]
        if seen > k:
            return i
    return counts.size - 1


@jit()
def integer_median_mad(d: np.ndarray):
    """``median(d)`` and ``median(|d - median(d)|)`` of float32 ``d`` holding small integers, by counting (:func:`ballscan.measure.detection._global_noise`).

    Returns ``(ok, med, mad)``; ``ok`` is False (and the values 0) unless
    every value is an integer and their range is at most ``2 d.size +
    1024``.  Then both medians are exact in float32 (integers and half or
    quarter integers below 2**21), so they are the values of the numpy
    form: the middle order statistic, or the mean of the two middle ones
    in float32.
    """
    n = d.size
    zero = np.float32(0.0)
    two = np.float32(2.0)
    if n == 0:
        return False, zero, zero
    iv = np.empty(n, dtype=np.int32)
    bad = False
    for q in range(n):
        v = d[q]
        bad |= not abs(v) <= np.float32(1048576.0)
        iv[q] = np.int32(v) if abs(v) <= np.float32(1048576.0) else 0
        bad |= np.float32(iv[q]) != v
    if bad:
        return False, zero, zero
    lo = iv.min()
    span = int(iv.max()) - int(lo) + 1
    if span > 2 * n + 1024:
        return False, zero, zero
    base = int(lo)
    counts = np.zeros(span, dtype=np.int64)
    for q in range(n):
        counts[iv[q] - base] += 1
    h = n // 2
    med = np.float32(_rank_in_counts(counts, h) + base)
    if n % 2 == 0:
        med = (np.float32(_rank_in_counts(counts, h - 1) + base) + med) / two
    # |v - med| doubled is an integer: count it
    dev = np.zeros(2 * span + 2, dtype=np.int64)
    for i in range(span):
        if counts[i]:
            dev[int(abs(2.0 * (np.float64(i + base) - np.float64(med))))] += counts[i]
    mad = np.float32(_rank_in_counts(dev, h)) / two
    if n % 2 == 0:
        mad = (np.float32(_rank_in_counts(dev, h - 1)) / two + mad) / two
    return True, med, mad


@jit()
def reflect_median_filter(x: np.ndarray, size: int) -> np.ndarray:
    """``scipy.ndimage.median_filter(x, size, mode="reflect")`` of a 1-D float64 ``x`` without NaN, ``size`` odd and below ``2 x.size`` (:func:`ballscan.measure.detection._background`).

    The windows hold the entries of ``x`` (mirrored at the ends, once, as
    ``d c b a | a b c d | d c b a``) with multiplicities 0 to 2; they are
    kept as counts over ``x`` sorted, and the middle rank is followed as
    the window slides by one (a few steps each), instead of a selection
    per window.
    """
    w = x.size
    r = size // 2
    order = np.argsort(x)
    pos = np.empty(w, dtype=np.int64)
    for q in range(w):
        pos[order[q]] = q
    cnt = np.zeros(w, dtype=np.int64)
    for t in range(-r, r + 1):
        cnt[pos[-t - 1 if t < 0 else (2 * w - 1 - t if t >= w else t)]] += 1
    # p: the sorted position holding rank r of the window; below: the window's entries before it
    p = 0
    below = 0
    while below + cnt[p] <= r:
        below += cnt[p]
        p += 1
    out = np.empty(w)
    out[0] = x[order[p]]
    for i in range(1, w):
        t_out = i - r - 1
        t_in = i + r
        a = pos[-t_out - 1 if t_out < 0 else (2 * w - 1 - t_out if t_out >= w else t_out)]
        b = pos[-t_in - 1 if t_in < 0 else (2 * w - 1 - t_in if t_in >= w else t_in)]
        cnt[a] -= 1
        if a < p:
            below -= 1
        cnt[b] += 1
        if b < p:
            below += 1
        while below > r:
            p -= 1
            below -= cnt[p]
        while below + cnt[p] <= r:
            below += cnt[p]
            p += 1
        out[i] = x[order[p]]
    return out


# error_model="numpy": no zero-division check (the divisors are positive),
# so the divisions vectorise (40 -> 23 us on a stream crop)
@jit(error_model="numpy")
def first_pass_lines(xs: np.ndarray, gain0: np.ndarray, offset0: np.ndarray, bs: np.ndarray, thr: np.ndarray, use_gain: bool):
    """Each line's drift samples with the first-pass ball pixels set to +inf, and their number per line (:func:`ballscan.measure.detection._background`).

    With ``use_gain`` a sample is ``xs / bs`` (``bs`` <= 0: excluded, divided
    by 1) and a pixel is excluded where ``|xs - gain0 bs| > thr``; else it
    is ``xs - bs``, excluded where ``|xs - bs - offset0| > thr``.  The same
    float64 operations as the numpy form (``xs`` float32, widened).
    """
    n, w = xs.shape
    s = np.empty((n, w))
    excluded = np.zeros(n, dtype=np.int64)
    safe = np.empty(w)
    for j in range(w):
        safe[j] = bs[j] if bs[j] > 0 else 1.0
    # one line at a time, in loops without branches (the compiler vectorises them)
    x = np.empty(w)
    for i in range(n):
        row = s[i]
        for j in range(w):
            x[j] = xs[i, j]
        e = 0
        if use_gain:
            g = gain0[i]
            for j in range(w):
                row[j] = x[j] / safe[j]
            for j in range(w):
                out = (abs(x[j] - g * bs[j]) > thr[j]) | (bs[j] <= 0)
                row[j] = np.inf if out else row[j]
                e += out
        else:
            o = offset0[i]
            for j in range(w):
                v = x[j] - bs[j]
                out = abs(v - o) > thr[j]
                row[j] = np.inf if out else v
                e += out
        excluded[i] = e
    return s, excluded


@jit()
def kept_median(s: np.ndarray, excluded: np.ndarray, big: float):
    """Per row of the row-sorted ``s`` (excluded values +inf, ``excluded`` of them): the masked median and the kept count (:func:`ballscan.measure.detection._masked_median`)."""
    n_row, n = s.shape
    med = np.zeros(n_row)
    count = n - excluded
    h = n // 2
    for i in range(n_row):
        if count[i] <= 0:
            continue
        n_low = excluded[i] // 2
        # ranks of the virtual row: n_low values -big, the kept ones, then +big
        hi = h - n_low
        v_hi = -big if hi < 0 else (big if hi >= count[i] else s[i, hi])
        if n % 2:
            med[i] = v_hi
        else:
            lo = hi - 1
            v_lo = -big if lo < 0 else (big if lo >= count[i] else s[i, lo])
            med[i] = (v_lo + v_hi) / 2
    return med, count


@jit()
def fill_lines_and_cols(m: np.ndarray) -> np.ndarray:
    """Union of the per-line and per-column hole fills of the bool mask ``m`` (:func:`ballscan.measure.detection.detect`).

    One sweep along the lines fills each line and finds each column's
    first and last pixel; a second fills the columns (line by line, in
    memory order).
    """
    h, w = m.shape
    out = np.zeros((h, w), dtype=np.bool_)
    first = np.full(w, h)
    last = np.full(w, -1)
    for i in range(h):
        a = -1
        b = -1
        for j in range(w):
            if m[i, j]:
                if a < 0:
                    a = j
                b = j
                first[j] = min(first[j], i)
                last[j] = i
        for j in range(a if a >= 0 else w, b + 1):
            out[i, j] = True
    for i in range(h):
        for j in range(w):
            out[i, j] |= (first[j] <= i) & (i <= last[j])
    return out


@jit()
def group_mask(lab: np.ndarray, l0: int, l1: int, c0: int, c1: int, in_group: np.ndarray) -> np.ndarray:
    """``in_group[lab[l0:l1, c0:c1]]``: the pixels of a group of labels in its box (:func:`ballscan.measure.detection.detect`)."""
    out = np.empty((l1 - l0, c1 - c0), dtype=np.bool_)
    for i in range(l1 - l0):
        for j in range(c1 - c0):
            out[i, j] = in_group[lab[l0 + i, c0 + j]]
    return out


@jit()
def multi_runs(m: np.ndarray, axis: int):
    """Lines (``axis=1``) or columns (``axis=0``) of the bool mask ``m`` in two or more runs of True: those with such a neighbour, and the others (:func:`ballscan.measure.detection._merged_runs`)."""
    h, w = m.shape
    if axis == 1:
        runs = np.zeros(h, dtype=np.int64)
        for i in range(h):
            for j in range(w):
                runs[i] += m[i, j] and (j == 0 or not m[i, j - 1])
    else:
        runs = np.zeros(w, dtype=np.int64)
        for j in range(w):
            runs[j] += m[0, j]
        for i in range(1, h):
            for j in range(w):
                runs[j] += m[i, j] and not m[i - 1, j]
    size = runs.size
    paired = np.zeros(size, dtype=np.bool_)
    lone = np.zeros(size, dtype=np.bool_)
    for k in range(size):
        if runs[k] >= 2:
            if (k > 0 and runs[k - 1] >= 2) or (k + 1 < size and runs[k + 1] >= 2):
                paired[k] = True
            else:
                lone[k] = True
    return paired, lone


@jit()
def region_values(x: np.ndarray, gain: np.ndarray, b: np.ndarray, offset: np.ndarray, l0: int, c0: int, mask: np.ndarray, sat: float):
    """Ball-minus-background values of the mask's pixels (in raster order) and whether any is at or above ``sat`` (:func:`ballscan.measure.detection.detect`).

    The box's background is ``gain * b + offset`` as in
    :func:`ballscan.measure.detection.background_at` (the same float64 operations).
    """
    h, w = mask.shape
    vals = np.empty(h * w)
    k = 0
    saturated = False
    for i in range(h):
        for j in range(w):
            if mask[i, j]:
                xv = x[l0 + i, c0 + j]
                vals[k] = xv - (gain[l0 + i] * b[c0 + j] + offset[l0 + i])
                saturated = saturated or xv >= sat
                k += 1
    return vals[:k].copy(), saturated


@jit(inline="always")
def _nan_last_less(a: float, b: float) -> bool:
    """``a`` sorts before ``b`` in numpy's order (NaN last)."""
    return a < b or (b != b and a == a)


@jit()
def walk_edges(p: np.ndarray, k_left: np.ndarray, k_right: np.ndarray, has_signal: np.ndarray, floor_p: np.ndarray, fraction: float, max_walk: int):
    """The rough edges of :func:`ballscan.measure.edges._edge_pass` walked outwards towards a darker (shaded) limb.

    On each line with signal, the left edge ``k`` moves to ``k - 1`` while
    that pixel holds ``fraction`` of its inner neighbour's value (``k + 1``)
    and at least ``floor_p``, at most ``max_walk`` times; the right edge
    likewise.  Returns new ``(k_left, k_right)``.
    """
    n, w = p.shape
    kl = k_left.copy()
    kr = k_right.copy()
    for r in range(n):
        if not has_signal[r]:
            continue
        for _ in range(max_walk):
            cand = kl[r] - 1
            inner = p[r, min(max(kl[r] + 1, 0), w - 1)]
            pc = p[r, min(max(cand, 0), w - 1)]
            if cand >= 0 and pc >= fraction * inner and pc >= floor_p[r]:
                kl[r] = cand
            else:
                break
        for _ in range(max_walk):
            cand = kr[r] + 1
            inner = p[r, min(max(kr[r] - 1, 0), w - 1)]
            pc = p[r, min(max(cand, 0), w - 1)]
            if cand <= w - 1 and pc >= fraction * inner and pc >= floor_p[r]:
                kr[r] = cand
            else:
                break
    return kl, kr


@jit()
def inner_differences(p: np.ndarray, sp: np.ndarray, k_left: np.ndarray, k_right: np.ndarray, has_signal: np.ndarray):
    """Second differences inside the segments of :func:`ballscan.measure.edges._edge_pass` (the ball's own noise).

    The pixels at least 3 inside both rough edges of a line with signal
    whose neighbours are such pixels too (not the box's first or last
    column): their second differences ``p[j-1] - 2 p[j] + p[j+1]``, values
    ``p`` and noise ``sp`` in row-major order (numpy's boolean indexing),
    and their count per column.
    """
    n, w = p.shape
    total = 0
    for r in range(n):
        if has_signal[r]:
            total += max(min(k_right[r] - 3, w - 2) - max(k_left[r] + 3, 1) - 1, 0)
    d2 = np.empty(total)
    pv = np.empty(total)
    sv = np.empty(total)
    per_col = np.zeros(w, dtype=np.int64)
    m = 0
    for r in range(n):
        if not has_signal[r]:
            continue
        # inner pixels j0..j1 (columns 1..w-2); "both" needs j-1 and j+1 inner too
        j0 = max(k_left[r] + 3, 1)
        j1 = min(k_right[r] - 3, w - 2)
        for j in range(j0 + 1, j1):
            d2[m] = (p[r, j - 1] - 2.0 * p[r, j]) + p[r, j + 1]
            pv[m] = p[r, j]
            sv[m] = sp[r, j]
            per_col[j] += 1
            m += 1
    return d2, pv, sv, per_col


@jit()
def edge_windows(
    p: np.ndarray,
    sp: np.ndarray,
    sat: np.ndarray,
    other: np.ndarray,
    k_left: np.ndarray,
    k_right: np.ndarray,
    n_out: np.ndarray,
    n_in: np.ndarray,
    n_level: int,
):
    """The window and level-run sums of every edge estimate of :func:`ballscan.measure.edges._edge_pass`.

    Rows ``4 n``: for each window variant ``v`` (``n_out[v]`` pixels outside
    the rough edge pixel besides the one next to it, ``n_in[v]`` inside) the
    left edges (sign +1) of the ``n`` lines, then the right ones (-1).  A
    window runs from ``k - (n_out + 1) s`` to ``k + n_in s`` (``s`` the
    sign), its level run the ``n_level`` pixels inside it, the deep run the
    next ``n_level`` and the deeper run the next (clipped to the box).  Sums
    in index order (numpy's for fewer than 8 terms: the same values).

    Returns
    -------
    tuple
        ``S`` (window sums), ``sw`` (4n, n_len: window pixels' sigmas, 0
        beyond a shorter window), ``sw2`` (their sums of squares),
        ``L_run``, ``sl2`` (mean and variance of the level run), ``pl0``,
        ``pl1``, ``sl0``, ``sl1`` (its first and last pixels' values and
        sigmas), ``pd``, ``sd2``, ``pdd``, ``sdd2`` (the deep and deeper
        runs' means and variances), ``win_first``, ``win_last``, ``n_win``,
        ``lev``, ``deep`` (4n, n_level: unclipped), ``sgn``, ``lo``, ``hi``
        (the extreme pixels of window and level run), ``inside_box``,
        ``saturated``, ``overlapping`` (a window or level pixel saturated or
        another ball's).
    """
    n, w = p.shape
    nv = n_out.shape[0]
    R = 2 * nv * n
    n_len = 0
    for v in range(nv):
        n_len = max(n_len, n_out[v] + n_in[v] + 2)
    S = np.empty(R)
    sw = np.zeros((R, n_len))
    sw2 = np.empty(R)
    L_run = np.empty(R)
    sl2 = np.empty(R)
    pl0 = np.empty(R)
    pl1 = np.empty(R)
    sl0 = np.empty(R)
    sl1 = np.empty(R)
    pd = np.empty(R)
    sd2 = np.empty(R)
    pdd = np.empty(R)
    sdd2 = np.empty(R)
    win_first = np.empty(R, dtype=np.int64)
    win_last = np.empty(R, dtype=np.int64)
    n_win = np.empty(R, dtype=np.int64)
    lev = np.empty((R, n_level), dtype=np.int64)
    deep = np.empty((R, n_level), dtype=np.int64)
    sgn = np.empty(R, dtype=np.int64)
    lo_px = np.empty(R, dtype=np.int64)
    hi_px = np.empty(R, dtype=np.int64)
    inside_box = np.empty(R, dtype=np.bool_)
    saturated = np.empty(R, dtype=np.bool_)
    overlapping = np.empty(R, dtype=np.bool_)
    nl2 = float(n_level * n_level)
    for i in range(R):
        q = i // n
        r = i - q * n
        v = q // 2
        s = 1 if q % 2 == 0 else -1
        k = k_left[r] if s > 0 else k_right[r]
        no = n_out[v]
        ni = n_in[v]
        length = no + ni + 2
        sgn[i] = s
        n_win[i] = length
        win_first[i] = k - (no + 1) * s
        win_last[i] = k + ni * s
        wmin = min(win_first[i], win_last[i])
        wmax = max(win_first[i], win_last[i])
        lv_a = k + (ni + 1) * s
        lv_b = k + (ni + n_level) * s
        lmin = min(lv_a, lv_b)
        lmax = max(lv_a, lv_b)
        inside_box[i] = wmin >= 0 and wmax < w and lmin >= 0 and lmax < w
        lo_px[i] = min(wmin, lmin)
        hi_px[i] = max(wmax, lmax)
        sat_any = False
        oth_any = False
        tS = 0.0
        tw2 = 0.0
        for j in range(n_len):
            # a shorter window is padded with its last pixel, out of the sums
            off = -(no + 1) + min(j, length - 1)
            c = min(max(k + off * s, 0), w - 1)
            sat_any = sat_any or sat[r, c]
            oth_any = oth_any or other[r, c]
            if j < length:
                tS += p[r, c]
                sw[i, j] = sp[r, c]
            tw2 += sw[i, j] * sw[i, j]
        S[i] = tS
        sw2[i] = tw2
        tl = 0.0
        tl2 = 0.0
        td = 0.0
        td2 = 0.0
        tdd = 0.0
        tdd2 = 0.0
        for j in range(n_level):
            a = k + (ni + 1 + j) * s
            lev[i, j] = a
            c = min(max(a, 0), w - 1)
            sat_any = sat_any or sat[r, c]
            oth_any = oth_any or other[r, c]
            if j == 0:
                pl0[i] = p[r, c]
                sl0[i] = sp[r, c]
            if j == n_level - 1:
                pl1[i] = p[r, c]
                sl1[i] = sp[r, c]
            tl += p[r, c]
            tl2 += sp[r, c] * sp[r, c]
            d = k + (ni + 1 + n_level + j) * s
            deep[i, j] = d
            c = min(max(d, 0), w - 1)
            td += p[r, c]
            td2 += sp[r, c] * sp[r, c]
            c = min(max(d + n_level * s, 0), w - 1)
            tdd += p[r, c]
            tdd2 += sp[r, c] * sp[r, c]
        L_run[i] = tl / n_level
        sl2[i] = tl2 / nl2
        pd[i] = td / n_level
        sd2[i] = td2 / nl2
        pdd[i] = tdd / n_level
        sdd2[i] = tdd2 / nl2
        saturated[i] = sat_any
        overlapping[i] = oth_any
    return (S, sw, sw2, L_run, sl2, pl0, pl1, sl0, sl1, pd, sd2, pdd, sdd2, win_first, win_last, n_win, lev, deep, sgn, lo_px, hi_px,
            inside_box, saturated, overlapping)


# ---------------------------------------------------------------------------
# Stream engine: the per-line band test and the block update's sums
# ---------------------------------------------------------------------------
# The engine tests every line of the stream (benchmarks/bench_stream.py:
# 2048-pixel lines at >= 140 000 lines/s) and a ball's result waits for the
# test of the lines up to its event's end.  As numpy expressions the test of
# 256 lines was some twenty whole-array passes (a wrapped difference, a
# comparison, the per-line offsets' gather and sort, the run rule on the
# candidate lines), about 0.5 ms; one pass per line over the stored values
# does the same with 8- or 16-bit lanes.  Each kernel exists for uint8 and
# for uint16 lines (one signature each); the bodies are shared.

@jit(inline="always")
def _max_excess_u8(row: np.ndarray, lo: np.ndarray, span: np.ndarray, o: int) -> int:
    """Largest ``((x - lo - o) mod 256) - span`` over ``row``, or 0 (no pixel outside the band)."""
    # every operation in uint8 lanes (the wrap is the modulo) and over the
    # whole row: LLVM vectorises this loop (~0.1 ns a pixel), which it did
    # not on int32 / int64 values or over 64-pixel blocks (~3 ns a pixel)
    o8 = np.uint8(o & 255)
    mx = np.uint8(0)
    for j in range(row.shape[0]):
        d = np.uint8(np.uint8(row[j] - lo[j]) - o8)
        e = np.uint8(d - span[j]) if d > span[j] else np.uint8(0)
        mx = max(mx, e)
    return np.int64(mx)


@jit(inline="always")
def _max_excess_u16(row: np.ndarray, lo: np.ndarray, span: np.ndarray, o: int) -> int:
    """:func:`_max_excess_u8` for uint16 values (modulo 65536)."""
    o16 = np.uint16(o & 65535)
    mx = np.uint16(0)
    for j in range(row.shape[0]):
        d = np.uint16(np.uint16(row[j] - lo[j]) - o16)
        e = np.uint16(d - span[j]) if d > span[j] else np.uint16(0)
        mx = max(mx, e)
    return np.int64(mx)


@jit(inline="always")
def _outside_u8(row: np.ndarray, lo: np.ndarray, span: np.ndarray, o: int, out: np.ndarray) -> None:
    """``out[j] = (x[j] - lo[j] - o) mod 256 > span[j]`` (1 or 0), vectorised as :func:`_max_excess_u8`."""
    o8 = np.uint8(o & 255)
    for j in range(row.shape[0]):
        d = np.uint8(np.uint8(row[j] - lo[j]) - o8)
        out[j] = np.uint8(1) if d > span[j] else np.uint8(0)


@jit(inline="always")
def _outside_u16(row: np.ndarray, lo: np.ndarray, span: np.ndarray, o: int, out: np.ndarray) -> None:
    """:func:`_outside_u8` for uint16 values (modulo 65536)."""
    o16 = np.uint16(o & 65535)
    for j in range(row.shape[0]):
        d = np.uint16(np.uint16(row[j] - lo[j]) - o16)
        out[j] = np.uint8(1) if d > span[j] else np.uint8(0)


@jit(inline="always")
def _select_int(buf: np.ndarray, m: int, k: int) -> int:
    """The ``k``-th smallest (0-based) of ``buf[:m]`` (Hoare's selection; reorders ``buf``)."""
    lo = 0
    hi = m - 1
    while lo < hi:
        p = buf[(lo + hi) >> 1]
        i = lo
        j = hi
        while i <= j:
            while buf[i] < p:
                i += 1
            while buf[j] > p:
                j -= 1
            if i <= j:
                t = buf[i]
                buf[i] = buf[j]
                buf[j] = t
                i += 1
                j -= 1
        if k <= j:
            hi = j
        elif k >= i:
            lo = i
        else:
            return buf[k]
    return buf[k]


@jit(inline="always")
def _kth_in_window(hist: np.ndarray, T: int, neg: int, k: int) -> int:
    """The ``k``-th smallest value (0-based), known to lie in ``[-T, T]``, of the values histogrammed in ``hist`` (bin ``v + T``); ``neg`` values are negative.

    Walks from 0 (where a line's offset usually is: a few steps) instead of
    summing the histogram from ``-T``.
    """
    if k < neg:
        # C(t) = values <= t; C(-1) = neg > k: the smallest t with C(t) > k is below 0
        t = -1
        c = neg
        while c - hist[t + T] > k:
            c -= hist[t + T]
            t -= 1
        return t
    t = 0
    c = neg + hist[T]
    while c <= k:
        t += 1
        c += hist[t + T]
    return t


@jit(inline="always")
def _line_offset(row: np.ndarray, ocols: np.ndarray, bg16: np.ndarray, max_off: int, buf: np.ndarray, hist: np.ndarray, T: int) -> int:
    """Offset (whole DN) of ``row`` from the background: ``clip(rint(median(16 x - bg16) / 16), -max_off, max_off)``.

    ``16 x - bg16`` over the columns ``ocols`` (fixed point, 4 fractional
    bits), the median the mean of the middle one or two values.  When both
    middle values lie in the window ``|v| <= T = 16 (max_off + 1)`` they are
    read off a histogram of the window (``hist``: ``2 T + 1`` zeros, left
    zeroed, or empty: then by selection); when both lie beyond one side
    the clipped offset is known (``+-max_off``); otherwise (a ball over
    about half the sampled columns) by selection.  The same value in every
    case: a histogram's cumulative count costs ~2 T steps against ~200
    unpredictable branches of a selection among 64 values.
    """
    m = ocols.shape[0]
    ka = (m - 1) // 2
    kb = m // 2
    below = 0
    above = 0
    neg = 0
    for c in range(m):
        v = (np.int64(row[ocols[c]]) << 4) - bg16[c]
        buf[c] = v
        # counts without branches (their outcomes are unpredictable)
        neg += v < 0
        below += v < -T
        above += v > T
    if kb < below:
        return -max_off  # (a + b) / 32 < -(max_off + 1)
    if ka >= m - above:
        return max_off
    if hist.shape[0] > 0 and ka >= below and kb < m - above:
        for c in range(m):
            v = buf[c]
            if -T <= v <= T:
                hist[v + T] += 1
        a = _kth_in_window(hist, T, neg, ka)
        b = a if kb == ka else _kth_in_window(hist, T, neg, kb)
        for c in range(m):
            v = buf[c]
            if -T <= v <= T:
                hist[v + T] = 0
    else:
        a = _select_int(buf, m, ka)
        b = a
        if kb != ka:
            # the smallest of the values above the ka-th
            b = buf[kb]
            for c in range(kb + 1, m):
                b = min(b, buf[c])
    v = np.rint((np.float64(a) + np.float64(b)) / 32.0)
    return np.int64(min(max(v, -np.float64(max_off)), np.float64(max_off)))


@jit(inline="always")
def _band_test(ring, first, n, lo, span, ocols, bg16, max_off, min_run, offsets, off_ring, hit_ring):
    """The body of :func:`stream_line_test_u8` / ``_u16`` (see there)."""
    cap, w = ring.shape
    wide = ring.itemsize > 1
    m = ocols.shape[0]
    buf = np.empty(m, dtype=np.int64)
    T = 16 * (max_off + 1)
    # a histogram of more than ~1000 bins (16-bit data's wide bands) costs
    # more than selection
    hist = np.zeros(2 * T + 1 if T <= 512 else 0, dtype=np.int64)
    flags = np.empty(w, dtype=np.uint8)
    idx = np.empty(n, dtype=np.int64)
    cnt = np.empty(n, dtype=np.int64)
    cmin = np.empty(n, dtype=np.int64)
    cmax = np.empty(n, dtype=np.int64)
    k = 0
    for i in range(n):
        r = (first + i) % cap
        row = ring[r]
        o = _line_offset(row, ocols, bg16, max_off, buf, hist, T) if offsets else 0
        off_ring[r] = o
        # first pass, vectorised: does the line hold an outside pixel at all
        # (most lines hold none; ~13 % of 2048-pixel lines one by chance)
        e = _max_excess_u16(row, lo, span, o) if wide else _max_excess_u8(row, lo, span, o)
        hit = False
        if e > 0:
            # the outside flags (vectorised), then the run rule over them
            if wide:
                _outside_u16(row, lo, span, o, flags)
            else:
                _outside_u8(row, lo, span, o, flags)
            run = 0
            count = 0
            j_first = -1
            j_last = -1
            for j in range(w):
                if flags[j]:
                    run += 1
                    if run >= min_run:
                        count += 1
                        if j_first < 0:
                            j_first = j - min_run + 1
                        j_last = j
                else:
                    run = 0
            if count > 0:
                hit = True
                idx[k] = i
                cnt[k] = count
                cmin[k] = j_first
                cmax[k] = j_last
                k += 1
        hit_ring[r] = hit
    return idx[:k], cnt[:k], cmin[:k], cmax[:k]


@jit()
def stream_line_test_u8(
    ring: np.ndarray,
    first: int,
    n: int,
    lo: np.ndarray,
    span: np.ndarray,
    ocols: np.ndarray,
    bg16: np.ndarray,
    max_off: int,
    min_run: int,
    offsets: bool,
    off_ring: np.ndarray,
    hit_ring: np.ndarray,
):
    """The stream engine's per-line test of ring rows ``first, first + 1, ...`` (``n`` rows, modulo the ring's length).

    Parameters
    ----------
    ring : numpy.ndarray
        uint8 (cap, W): stored values (DN).
    lo, span : numpy.ndarray
        uint8 (W,): the band ``[lo, lo + span]`` of each column (DN).
    ocols : numpy.ndarray
        int64: the columns of the per-line offset.
    bg16 : numpy.ndarray
        int64: ``rint(16 * background)`` at ``ocols`` (1/16 DN).
    max_off : int
        Clip of the per-line offset (whole DN).
    min_run : int
        Adjacent outside pixels that make a hit line.
    offsets : bool
        Shift each line's band by its offset (else offset 0).
    off_ring : numpy.ndarray
        int32 (cap,): receives each tested row's offset (DN).
    hit_ring : numpy.ndarray
        bool (cap,): receives whether each tested row is a hit line.

    Returns
    -------
    tuple of numpy.ndarray
        int64, one value per hit line: its index among the ``n`` rows, the
        number of run positions (pixels ``j`` starting ``min_run`` outside
        pixels), the first such ``j`` and the last one plus ``min_run - 1``
        (the numpy form's ``counts``, ``cmin``, ``cmax``). A pixel is outside
        when ``(x - lo - o) mod 256 > span`` (``o`` the line's offset).
    """
    return _band_test(ring, first, n, lo, span, ocols, bg16, max_off, min_run, offsets, off_ring, hit_ring)


@jit()
def stream_line_test_u16(
    ring: np.ndarray,
    first: int,
    n: int,
    lo: np.ndarray,
    span: np.ndarray,
    ocols: np.ndarray,
    bg16: np.ndarray,
    max_off: int,
    min_run: int,
    offsets: bool,
    off_ring: np.ndarray,
    hit_ring: np.ndarray,
):
    """:func:`stream_line_test_u8` for uint16 ``ring``, ``lo`` and ``span`` (modulo 65536)."""
    return _band_test(ring, first, n, lo, span, ocols, bg16, max_off, min_run, offsets, off_ring, hit_ring)


@jit(inline="always")
def _block_sums(ring, off_ring, rows):
    """The body of :func:`stream_block_sums_u8` / ``_u16``."""
    w = ring.shape[1]
    t1 = np.zeros(w, dtype=np.int64)
    t2 = np.zeros(w, dtype=np.int64)
    for q in range(rows.shape[0]):
        r = rows[q]
        o = np.int64(off_ring[r])
        row = ring[r]
        for j in range(w):
            v = np.int64(row[j]) - o
            t1[j] += v
            t2[j] += v * v
    return t1.astype(np.float64), t2.astype(np.float64)


@jit()
def stream_block_sums_u8(ring: np.ndarray, off_ring: np.ndarray, rows: np.ndarray):
    """Per-column sums of ``x - o`` and of ``(x - o)**2`` over the ring rows ``rows`` (``o`` each row's offset).

    Parameters
    ----------
    ring : numpy.ndarray
        uint8 (cap, W): stored values (DN).
    off_ring : numpy.ndarray
        int32 (cap,): per-row offsets (DN).
    rows : numpy.ndarray
        int64: the rows summed.

    Returns
    -------
    tuple of numpy.ndarray
        float64 (W,) each (DN, DN^2): exact (integer sums, below 2**53).
    """
    return _block_sums(ring, off_ring, rows)


@jit()
def stream_block_sums_u16(ring: np.ndarray, off_ring: np.ndarray, rows: np.ndarray):
    """:func:`stream_block_sums_u8` for a uint16 ``ring``."""
    return _block_sums(ring, off_ring, rows)


def warm_up_stream() -> None:
    """Load (or compile) the stream engine's kernels now, on tiny inputs (part of :func:`warm_up`).

    A stream whose estimates run in other processes loads only these.
    """
    ocols = np.zeros(1, dtype=np.int64)
    rows = np.zeros(1, dtype=np.int64)
    off = np.zeros(1, dtype=np.int32)
    hit = np.zeros(1, dtype=np.bool_)
    for dt, test, sums in ((np.uint8, stream_line_test_u8, stream_block_sums_u8), (np.uint16, stream_line_test_u16, stream_block_sums_u16)):
        ring = np.zeros((1, 2), dtype=dt)
        band = np.zeros(2, dtype=dt)
        test(ring, 0, 1, band, band, ocols, ocols, 1, 2, True, off, hit)
        sums(ring, off, rows)


# ---------------------------------------------------------------------------
# Limb and shading: the edges' limb levels from the shading model
# ---------------------------------------------------------------------------
# The second edge pass (ballscan.measure.edges._limb_levels) evaluates the shading
# model on the ten pixels of each of some three hundred edge windows, three
# times (two placements of the edge and the texture test).  As numpy
# expressions that was some two hundred operations on arrays of a few
# thousand entries (the whole pixels' coverage, the point samples of the
# partly covered pixels, the surface's brightness, the nearest-pixel fill
# and the rounds' ratios), 3-4 ms a ball; the rows are independent, and one
# loop over them does the same arithmetic in the same order.  (numpy's error
# model: a division by zero gives inf or NaN, which the rules reject, as
# the numpy form's did.)


@jit(inline="always")
def _normalised(u: float, principal: float, focal: float, k1: float, k2: float):
    """Undistorted normalised coordinate of sensor position ``u`` and whether it converged (:meth:`ballscan.geometry.camera.LineScanCamera.backproject`).

    Newton's method on ``n (1 + k1 n^2 + k2 n^4) = (u - principal) / focal``
    to 1e-12 pixels a step, as the camera's (which stops when every
    element of its array has; the few more steps there change ``n`` below
    that), then converged where the residual is within 1e-9 pixels.
    """
    n_d = (u - principal) / focal
    if k1 == 0.0 and k2 == 0.0:
        return n_d, True
    tol = 1e-9 / focal
    n = n_d
    for _ in range(50):
        n2 = n * n
        step = (n * (1.0 + k1 * n2 + k2 * n2 * n2) - n_d) / (1.0 + 3.0 * k1 * n2 + 5.0 * k2 * n2 * n2)
        n = n - step
        if abs(step) < tol * 1e-3:
            break
    n2 = n * n
    return n, abs(n * (1.0 + k1 * n2 + k2 * n2 * n2) - n_d) <= tol


@jit(inline="always")
def _limb_point(o, sg, edge_m, bg_row, width, cen, nt, hs, nh, focal, principal, k1, k2, R2, light, ambient, scale):
    """The model's normalised value and coverage at offset ``o`` (pixels inwards) from a row's mean edge ``edge_m``, and whether its ray converged (:func:`_limb_rays`)."""
    u = edge_m + sg * o
    # the background's column: clamped, then rounded (as LimbProfile.__call__)
    col = int(np.rint(min(max(u, 0.0), width - 1.0)))
    nu, ok = _normalised(u, principal, focal, k1, k2)
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
    if not _ramp_histogram(c_lo[r], c_hi[r], c_w[r], base - 0.5, span, hwb[0], hwb[1]):
        return False, True
    rays_ok = True
    n_missing = 0
    for k in range(K):
        cov[k] = _grid_coverage(hwb[0], hwb[1], int(np.rint(off[k] - base)))
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


@jit(error_model="numpy")
def limb_levels(
    sg: np.ndarray,
    px: np.ndarray,
    n_win: np.ndarray,
    kw: int,
    n_level: int,
    e0: np.ndarray,
    var0: np.ndarray,
    L0: np.ndarray,
    S: np.ndarray,
    L_run: np.ndarray,
    sl2: np.ndarray,
    sw: np.ndarray,
    q_data: np.ndarray,
    q_lim: np.ndarray,
    n_points: int,
    c_lo: np.ndarray,
    c_hi: np.ndarray,
    c_w: np.ndarray,
    t_rows: np.ndarray,
    edge_m: np.ndarray,
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
    model's window value per covered length over its level run's (rejected
    outside [0.5, 2] or below 0.05 px of covered length) and moving the
    edge by the model's covered length less the data's ``S / L``; the
    texture test compares ``q_data`` with the model's ratio at the new edge
    (within ``q_lim``).  Rows
    that fail keep ``e0, var0, L0``.  ``n_points`` point samples per partly
    covered pixel.

    Returns
    -------
    edge, var, L : ndarray (R,)
    rays_ok : bool
        False when the inverse distortion of a ray did not converge.
    """
    R, K = px.shape
    nd = K - kw - n_level
    edge = e0.copy()
    var = var0.copy()
    L = L0.copy()
    # the unit grid's span: the rows' offsets differ by whole pixels
    span = 0
    for r in range(R):
        lo_px = np.inf
        hi_px = -np.inf
        for k in range(K):
            lo_px = min(lo_px, px[r, k])
            hi_px = max(hi_px, px[r, k])
        span = max(span, int(np.rint(hi_px - lo_px)) + 1)
    hwb = np.empty((2, span + 2))
    frac = (np.arange(n_points) + 0.5) / n_points
    point = np.full((R, K), np.nan)
    wk = np.empty((4, K))
    cov = wk[1]
    val = wk[3]
    R2 = radius_m * radius_m
    has_acc = acc[0] != 0.0 or acc[1] != 0.0 or acc[2] != 0.0
    width = background.shape[1]
    law = np.array([focal, principal, k1, k2, R2, ambient, scale])
    cen_pt = np.empty((max(tk.shape[0], 1), 4))
    hs_pt = np.empty(max(hk.shape[0], 1))
    cen_c = np.empty((1, 4))
    hs_c = np.empty(1)
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
            fine, ok = _limb_row_profile(
                r, at, sg[r], px, c_lo, c_hi, c_w, span, hwb, frac, rnd == 0, point, wk, n_use, kw, run_hi,
                edge_m[r], bg_row, width, cen_pt, nt_pt, hs_pt, nh_pt, cen_c, hs_c, law, light,
            )
            rays_ok = rays_ok and ok
            if not fine:
                break
            if rnd == 2:
                break
            s_model = 0.0
            c_model = 0.0
            for k in range(kw):
                if k < n_win[r]:
                    s_model += val[k]
                    c_model += cov[k]
            lev = 0.0
            for k in range(kw, kw + n_level):
                lev += val[k]
            ratio = s_model / c_model / (lev / n_level)
            usable = np.isfinite(ratio) and c_model > 0.05 and ratio >= 0.5 and ratio <= 2.0
            if not usable:
                ratio = 1.0
            Lr = L_run[r] * ratio
            covered = S[r] / (Lr if Lr > 0.0 else 1.0)
            er = at + sg[r] * (c_model - covered) if usable else e0[r]
        if not fine:
            # no coverage (a NaN chord sample): the model-free edge
            continue
        # texture test with the model at the new edge (the third profile)
        run_in = 0.0
        for k in range(kw, kw + n_level):
            run_in += val[k]
        run_deep = 0.0
        for k in range(kw + n_level, K):
            run_deep += val[k]
        q_model = (run_deep / nd) / (run_in / n_level)
        smooth = abs(q_data[r] - q_model) <= q_lim[r]
        if usable and smooth:
            Ls = Lr if Lr > 0.0 else 1.0
            s_w2 = 0.0
            for k in range(sw.shape[1]):
                s_w2 += sw[r, k] ** 2
            edge[r] = er
            var[r] = s_w2 / Ls**2 + (S[r] / Ls**2) ** 2 * sl2[r] * ratio**2
            L[r] = Lr
    return edge, var, L, rays_ok


# ---------------------------------------------------------------------------
# Limb and shading: the shading law's robust fit
# ---------------------------------------------------------------------------
# ballscan.measure.shading.fit_shading reweights a four-parameter least-squares fit
# of some 800 interior pixels four times, then the flat law four times: as
# numpy that was some hundred and fifty calls (the rounds' lstsq, two full
# sorts for each round's median and MAD, the weights), 0.6 ms a ball.  The
# loop below makes the same calls into LAPACK (gelsd) and BLAS (gemv) and
# sums as numpy does (pairwise), so the law is the same to the last bit.


@jit()
def _pairwise_sum(a: np.ndarray) -> float:
    """``np.sum`` of a contiguous float64 array: numpy's pairwise summation (blocks of 128 in eight lanes)."""
    n = a.shape[0]
    if n < 8:
        res = 0.0
        for i in range(n):
            res += a[i]
        return res
    if n <= 128:
        r0, r1, r2, r3, r4, r5, r6, r7 = a[0], a[1], a[2], a[3], a[4], a[5], a[6], a[7]
        m = n - n % 8
        for i in range(8, m, 8):
            r0 += a[i]
            r1 += a[i + 1]
            r2 += a[i + 2]
            r3 += a[i + 3]
            r4 += a[i + 4]
            r5 += a[i + 5]
            r6 += a[i + 6]
            r7 += a[i + 7]
        res = ((r0 + r1) + (r2 + r3)) + ((r4 + r5) + (r6 + r7))
        for i in range(m, n):
            res += a[i]
        return res
    n2 = n // 2
    n2 -= n2 % 8
    return _pairwise_sum(a[:n2]) + _pairwise_sum(a[n2:])


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
    level = _pairwise_sum(y) / N
    flat_scale = 1.0
    for _ in range(n_iterations):
        for i in range(N):
            b[i] = w[i] * y[i]
        level = _pairwise_sum(b) / _pairwise_sum(w)
        for i in range(N):
            r[i] = y[i] - level
        flat_scale = _huber_weights(r, huber_k, w, buf)
    if flat_scale <= (1.0 + flat_tol) * scale:
        coef = np.zeros(4)
        coef[0] = level
        scale = flat_scale
    return coef, scale


# ---------------------------------------------------------------------------
# Limb and shading: the model's line levels and their measured scatter
# ---------------------------------------------------------------------------
# The ends' line levels (LimbProfile.line_levels) and their scatter on the
# plateau lines (ballscan.measure.shading._line_level_scatter) evaluate the model on
# some forty lines each; as numpy they were some sixty operations on arrays
# of a few thousand entries (0.5 ms a ball together).  The rows' sums are
# numpy's pairwise sums (_pairwise_sum), so the results are its bits.


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
        val_sum[r] = _pairwise_sum(bv)
        cov_sum[r] = _pairwise_sum(bc)
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
        m_mean = _pairwise_sum(bm) / n
        di = _pairwise_sum(bp) / n / m_mean - 1.0
        vi = _pairwise_sum(bs) / (n * n) / m_mean**2
        if np.isfinite(di) and np.isfinite(vi) and m_mean > 0.05:
            d[n_good] = di * di
            v[n_good] = vi
            n_px[n_good] = n
            n_good += 1
    if n_good < 3:
        return np.nan, 1.0, rays_ok
    return math.sqrt(max(_pairwise_sum(d[:n_good]) / n_good - _pairwise_sum(v[:n_good]) / n_good, 0.0)), _pairwise_sum(n_px[:n_good]) / n_good, rays_ok


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
        nu, ok = _normalised(float(cols[i]), principal, focal, k1, k2)
        rays_ok = rays_ok and ok
        _centres(t_rows[i], True, no_instants, pos, vel, acc, has_acc, t_c, cen)
        cx, cy, cz, c2 = cen[0, 0], cen[0, 1], cen[0, 2], cen[0, 3]
        h = 0.0 / focal
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
            hit[i] = True
            normals[i, 0] = nx * a
            normals[i, 1] = ny * a
            normals[i, 2] = nz * a
    return hit, normals, rays_ok


# ---------------------------------------------------------------------------
# Column gains: the masked medians of ballscan.measure.flatfield.column_gains
# ---------------------------------------------------------------------------
# column_gains takes three medians of the masked pixels of a ball's box: each
# line's, each column's and each column's absolute deviation from it.  numpy's
# sort of the box with inf where unmasked stays (15 us, faster than a
# compiled selection: 50 us); the middle ranks are picked here (as numpy the
# mask's counts and two gathers, another 20 us of small calls), and the
# deviations' median is merged from the same sorted columns instead of a
# second sort.


@jit()
def sorted_medians(v: np.ndarray, mask: np.ndarray, axis: int) -> np.ndarray:
    """Medians of the masked values from the sorted box of :func:`ballscan.measure.flatfield._masked_median`.

    ``v`` is ``where(mask, values, inf)`` sorted along ``axis`` (0 or 1) of
    a 2-D array: along it each line (or column) of ``n`` masked values has
    its median at ranks ``(n - 1) // 2`` and ``n // 2``, ``0.5 * (lo +
    hi)``; NaN where ``n`` is 0.
    """
    n_a, n_b = v.shape
    n_out = n_b if axis == 0 else n_a
    n_along = n_a if axis == 0 else n_b
    out = np.empty(n_out)
    for o in range(n_out):
        n = 0
        for i in range(n_along):
            if (mask[i, o] if axis == 0 else mask[o, i]):
                n += 1
        if n == 0:
            out[o] = np.nan
            continue
        lo = (n - 1) // 2
        hi = n // 2
        if axis == 0:
            out[o] = 0.5 * (v[lo, o] + v[hi, o])
        else:
            out[o] = 0.5 * (v[o, lo] + v[o, hi])
    return out


@jit()
def median_deviations(v: np.ndarray, mask: np.ndarray):
    """Each row's median of the masked values and their median absolute deviation from it (:func:`ballscan.measure.flatfield._column_median_mad`).

    ``v`` is ``where(mask, values, inf)`` sorted along its rows (the box's
    columns, transposed); the median as :func:`sorted_medians`.  Where a
    row's first and ``n``-th sorted values are finite they are its ``n``
    masked values, and the deviations ``|x - med|`` in ascending order are
    those below the median walked down (``med - x``, the same value:
    rounding is symmetric) merged with those above walked up: their middle
    ranks are the deviations' median, ``0.5 * (lo + hi)``, without a second
    sort.

    Returns
    -------
    med, mad : ndarray (n_rows,)
        NaN where a row has no masked value; ``mad`` also NaN where not
        measured so (see ``exact``).
    exact : bool
        False when a row's masked values are not all finite (its deviations
        must be sorted as they are).
    """
    n_rows, n_along = v.shape
    med = np.empty(n_rows)
    mad = np.empty(n_rows)
    exact = True
    for o in range(n_rows):
        x = v[o]
        n = 0
        for i in range(n_along):
            if mask[o, i]:
                n += 1
        if n == 0:
            med[o] = np.nan
            mad[o] = np.nan
            continue
        lo = (n - 1) // 2
        hi = n // 2
        m = 0.5 * (x[lo] + x[hi])
        med[o] = m
        if not (math.isfinite(x[0]) and math.isfinite(x[n - 1])):
            exact = False
            mad[o] = np.nan
            continue
        below = 0
        while below < n and x[below] <= m:
            below += 1
        i = below - 1
        j = below
        d_lo = 0.0
        d_hi = 0.0
        for rank in range(hi + 1):
            if j >= n or (i >= 0 and m - x[i] <= x[j] - m):
                d = m - x[i]
                i -= 1
            else:
                d = x[j] - m
                j += 1
            if rank == lo:
                d_lo = d
            if rank == hi:
                d_hi = d
        mad[o] = 0.5 * (d_lo + d_hi)
    return med, mad, exact


# ---------------------------------------------------------------------------
# Edge measurement: the first pass's and the finish's small array passes
# ---------------------------------------------------------------------------
# After the windows' sums (edge_windows) ballscan.measure.edges._edge_pass and
# _finish were some hundred numpy expressions of a few microseconds each on
# the box (the rough edges, the shot noise's sigmas, the lines' summed
# coverage) or on the edges' rows (the level gradients and their running
# medians, the shading decision per side, the levels, edges and variances,
# the usable edges and the lines' fields, the limb levels' pixel centres):
# 0.3 ms of a stream ball's 0.64 ms measure_edges.  Each loop below does the
# same arithmetic in the same order (sums in numpy's pairwise order), so the
# values are the same bit for bit.

# np.nan_to_num's value for an infinity
_FLOAT_MAX = float(np.finfo(np.float64).max)


@jit()
def rough_edges(p: np.ndarray, peak: np.ndarray, fraction: float):
    """Each line's first and last pixel whose ``p`` reaches ``fraction`` of its ``peak`` (0 and the last pixel where none does; :func:`ballscan.measure.edges._edge_pass`).

    Returns
    -------
    k_left, k_right : ndarray of int64 (n,)
    """
    n, w = p.shape
    k_left = np.zeros(n, dtype=np.int64)
    k_right = np.full(n, w - 1, dtype=np.int64)
    for r in range(n):
        t = fraction * peak[r]
        for j in range(w):
            if p[r, j] >= t:
                k_left[r] = j
                break
        for j in range(w - 1, -1, -1):
            if p[r, j] >= t:
                k_right[r] = j
                break
    return k_left, k_right


@jit(error_model="numpy")
def shot_noise(p: np.ndarray, sp: np.ndarray, excess: float, p_in: float) -> np.ndarray:
    """The pixels' noise with the ball's shot noise, ``sqrt(sp**2 + excess * clip(q / p_in, 0, 2))`` (:func:`ballscan.measure.edges._edge_pass`).

    ``q`` is each pixel's signal from the lines before and after it (same
    column): the mean of the two neighbours (the one neighbour on the box's
    first and last line; the pixel itself on a one-line box).  Not the
    pixel's own value: a variance that grows with its own noisy value gives
    the pixels that read high less weight, and every weighted estimate that
    uses it (the windows' sums, the matched edges' weights, the pixel fit)
    reads the ball small: on the quick sweep's long balls (R = 0.11 m and
    140 000 lines/s, 8-bit, shot noise, 32 seeds each) the speed read 0.23
    +- 0.015 and 0.08 +- 0.006 sigma of the pixel bound higher than with the
    neighbours' signal (the same images).  Their noise is independent of the
    pixel's; where the coverage changes from line to line (a ball's ends)
    their mean still follows it to first order.  The clip keeps NaN, as
    numpy's does.
    """
    n, w = p.shape
    out = np.empty((n, w))
    for r in range(n):
        for j in range(w):
            if n < 2:
                q = p[r, j]
            elif r == 0:
                q = p[1, j]
            elif r == n - 1:
                q = p[n - 2, j]
            else:
                q = 0.5 * (p[r - 1, j] + p[r + 1, j])
            t = q / p_in
            if t == t:
                t = t if t > 0.0 else 0.0
                t = t if t < 2.0 else 2.0
            out[r, j] = math.sqrt(sp[r, j] * sp[r, j] + excess * t)
    return out


@jit(error_model="numpy")
def line_coverage(p: np.ndarray, sp: np.ndarray, k_left: np.ndarray, k_right: np.ndarray, has_signal: np.ndarray, c0: int):
    """Each line's summed coverage, its sigma and its centroid (:func:`ballscan.measure.edges._edge_pass`).

    Over the columns ``k_left - 3`` to ``k_right + 3`` of a line with
    signal, else the whole line: ``area = sum p``, ``area_sig = sqrt(sum
    sp^2)`` and ``centroid = sum p (j + c0) / area``, NaN unless ``area >
    3 area_sig``.  Each sum is numpy's of the line with zeros outside the
    columns (pairwise, :func:`_pairwise_sum`).
    """
    n, w = p.shape
    area = np.empty(n)
    area_sig = np.empty(n)
    centroid = np.empty(n)
    b_p = np.empty(w)
    b_s = np.empty(w)
    b_c = np.empty(w)
    for r in range(n):
        lo = k_left[r] - 3 if has_signal[r] else 0
        hi = k_right[r] + 3 if has_signal[r] else w - 1
        for j in range(w):
            if lo <= j <= hi:
                b_p[j] = p[r, j]
                b_s[j] = sp[r, j] * sp[r, j]
                b_c[j] = p[r, j] * float(j + c0)
            else:
                b_p[j] = 0.0
                b_s[j] = 0.0
                b_c[j] = 0.0
        area[r] = _pairwise_sum(b_p)
        area_sig[r] = math.sqrt(_pairwise_sum(b_s))
        centroid[r] = _pairwise_sum(b_c) / area[r] if area[r] > 3.0 * area_sig[r] else np.nan
    return area, area_sig, centroid


@jit(error_model="numpy")
def level_gradients(
    pl0: np.ndarray,
    pl1: np.ndarray,
    pd: np.ndarray,
    L_run: np.ndarray,
    sl0: np.ndarray,
    sl1: np.ndarray,
    sd2: np.ndarray,
    sl2: np.ndarray,
    has_signal: np.ndarray,
    n_in: np.ndarray,
    n_level: int,
    slope_lines: int,
):
    """The relative level gradient of each edge row of :func:`ballscan.measure.edges._edge_pass` and its variance as a median of ``slope_lines``.

    Rows as :func:`edge_windows` (``2 n`` per window variant, ``n_in[v]``
    its pixels inside the rough edge): the gradient per pixel across the
    level run (first and last pixels ``pl0, pl1``, sigmas ``sl0, sl1``; with
    a one-pixel run, the deep run ``pd`` against it), times ``-dist /
    L_run`` (``dist`` from the run's centre to the edge pixel's covered
    part, ``L_run`` 1 where 0), NaN on lines without signal; each operation
    as the numpy form's.

    Returns
    -------
    raw_rel, rel_var, rel_sig : ndarray (R,)
    """
    R = pl0.shape[0]
    per_variant = R // n_in.shape[0]
    raw_rel = np.empty(R)
    rel_var = np.empty(R)
    rel_sig = np.empty(R)
    for i in range(R):
        dist = float(n_in[i // per_variant] + 1) + (n_level - 1) / 2.0 - 0.25
        Lsafe = L_run[i] if abs(L_run[i]) > 0.0 else 1.0
        if n_level >= 2:
            grad = (pl1[i] - pl0[i]) / float(n_level - 1)
            g_var = (sl1[i] * sl1[i] + sl0[i] * sl0[i]) / float((n_level - 1) ** 2)
        else:
            grad = (pd[i] - L_run[i]) / float(n_level)
            g_var = (sd2[i] + sl2[i]) / float(n_level**2)
        raw_rel[i] = -dist * grad / Lsafe if has_signal[i] else np.nan
        rel_var[i] = dist * dist * g_var / (Lsafe * Lsafe) * (math.pi / 2.0) / float(max(slope_lines, 1))
        rel_sig[i] = math.sqrt(rel_var[i])
    return raw_rel, rel_var, rel_sig


@jit()
def running_medians(x: np.ndarray, n_blocks: int, n: int) -> np.ndarray:
    """The running median of :func:`ballscan.measure.edges._running_median` over each of ``n_blocks`` equal blocks of ``x`` (the edges' four sides at once).

    The same values: each window is kept sorted in numpy's order (NaN last)
    and, among equal values, in index order, as :func:`running_median`'s
    insertion sort leaves it; a step drops the oldest entry and inserts the
    newest instead of sorting the window anew (whose unpredictable
    comparisons were most of its time on the crops).
    """
    size = x.shape[0] // n_blocks
    h = n // 2
    wl = 2 * h + 1
    out = np.empty(x.shape[0])
    buf = np.empty(wl)
    idx = np.empty(wl, dtype=np.int64)
    for blk in range(n_blocks):
        x0 = blk * size
        m = 0
        cnt = 0
        for i in range(-h, size + h):
            v = x[x0 + i] if 0 <= i < size else np.nan
            if m == wl:
                # drop the window's oldest entry (index i - wl)
                k = 0
                while idx[k] != i - wl:
                    k += 1
                if math.isfinite(buf[k]):
                    cnt -= 1
                for q in range(k, m - 1):
                    buf[q] = buf[q + 1]
                    idx[q] = idx[q + 1]
                m -= 1
            if math.isfinite(v):
                cnt += 1
            # after every entry it does not sort before (the newest index)
            p = m
            while p > 0 and _nan_last_less(v, buf[p - 1]):
                buf[p] = buf[p - 1]
                idx[p] = idx[p - 1]
                p -= 1
            buf[p] = v
            idx[p] = i
            m += 1
            c = i - h
            if c >= 0:
                if cnt == 0:
                    out[x0 + c] = np.nan
                else:
                    lo = max(cnt - 1, 0) // 2
                    hi = min(cnt // 2, wl - 1)
                    out[x0 + c] = 0.5 * (buf[lo] + buf[hi])
    return out


@jit()
def shaded_sides(rel: np.ndarray, rel_sig: np.ndarray, use: np.ndarray, n_sides: int, threshold: float) -> np.ndarray:
    """The smoothed relative level gradients of :func:`ballscan.measure.edges._edge_pass` that are applied, 0 elsewhere.

    ``rel`` holds ``n_sides`` equal blocks of rows (a window's left or
    right edges); NaN becomes 0 and an infinity the largest float (as
    ``np.nan_to_num``), and a block is zeroed unless the mean of ``|rel| /
    rel_sig`` over its ``use`` rows (numpy's pairwise sum over their count)
    exceeds ``threshold``.
    """
    R = rel.shape[0]
    n = R // n_sides
    out = np.empty(R)
    for i in range(R):
        v = rel[i]
        if v != v:
            v = 0.0
        elif v == np.inf:
            v = _FLOAT_MAX
        elif v == -np.inf:
            v = -_FLOAT_MAX
        out[i] = v
    buf = np.empty(n)
    for q in range(n_sides):
        m = 0
        for i in range(q * n, (q + 1) * n):
            if use[i]:
                buf[m] = abs(out[i]) / rel_sig[i]
                m += 1
        if not (m > 0 and _pairwise_sum(buf[:m]) / m > threshold):
            out[q * n : (q + 1) * n] = 0.0
    return out


@jit(error_model="numpy")
def window_edges(
    rel: np.ndarray,
    rel_var: np.ndarray,
    L_run: np.ndarray,
    S: np.ndarray,
    sw2: np.ndarray,
    sl2: np.ndarray,
    n_win: np.ndarray,
    win_first: np.ndarray,
    win_last: np.ndarray,
    sgn: np.ndarray,
    kap: float,
    kap2: float,
):
    """The model-free edges of :func:`ballscan.measure.edges._edge_pass`: level, edge and variance of each edge row.

    The level ``L = L_run (1 + kap rel)`` (``rel`` the applied relative
    gradient, 0 where not), the edge from the window's uncovered length
    ``n_win - S / L`` (``L`` 1 where not positive) at its outermost pixel
    and its variance from the window's and the level run's noise (and the
    gradient's, ``kap2 rel_var``, where applied); each operation as the
    numpy form's (``kap2`` is its ``kap**2``).

    Returns
    -------
    L, e, var : ndarray (R,)
    """
    R = rel.shape[0]
    L = np.empty(R)
    e = np.empty(R)
    var = np.empty(R)
    for i in range(R):
        f = 1.0 + kap * rel[i]
        L[i] = L_run[i] * f
        Ls = L[i] if L[i] > 0.0 else 1.0
        uncovered = n_win[i] - S[i] / Ls
        # left: the window starts at its outermost pixel a; right: ends at b
        if sgn[i] > 0:
            e[i] = (min(win_first[i], win_last[i]) - 0.5) + uncovered
        else:
            e[i] = (max(win_first[i], win_last[i]) + 0.5) - uncovered
        Ls2 = Ls * Ls
        u = S[i] / Ls2
        v = sw2[i] / Ls2 + u * u * sl2[i] * (f * f)
        c = S[i] / Ls
        var[i] = v + (c * c * kap2 * rel_var[i] if rel[i] != 0.0 else 0.0)
    return L, e, var


@jit(error_model="numpy")
def finished_edges(
    e: np.ndarray,
    var: np.ndarray,
    L: np.ndarray,
    S: np.ndarray,
    n_win: np.ndarray,
    dlev: np.ndarray,
    run_ok: np.ndarray,
    L_run: np.ndarray,
    usable: np.ndarray,
    has_signal: np.ndarray,
    spoiled: np.ndarray,
    c0: int,
):
    """The per-line fields of :func:`ballscan.measure.edges._finish` from the edges' rows (4 n: narrow left, right, wide left, right).

    Each edge is usable where ``usable``, its level run is (``run_ok``) and
    its level plausible: ``L > L_run / 2`` and the uncovered length ``n_win
    - S / L`` (L 1 where not positive) within ``[-0.5, n_win + 0.5]``.  On
    the lines with signal the edges ``e + c0`` (sensor pixels), their sigmas
    ``sqrt(var)`` and the narrow edges' texture ``S / L * dlev / L``, NaN on
    the others; each line's level (the mean of a usable pair's, or the one
    usable, NaN) and whether it is an end line (signal, no usable pair, not
    ``spoiled``).

    Returns
    -------
    ok : ndarray of bool (4 n,)
    edge, sigma : ndarray (4, n)
        By window and side, as the rows.
    texture : ndarray (2, n)
        Narrow window, left and right.
    level : ndarray (n,)
    end_line : ndarray of bool (n,)
    """
    R = e.shape[0]
    n = R // 4
    ok = np.empty(R, dtype=np.bool_)
    for i in range(R):
        Ls = L[i] if L[i] > 0.0 else 1.0
        uncovered = n_win[i] - S[i] / Ls
        ok[i] = usable[i] and run_ok[i] and L[i] > 0.5 * L_run[i] and uncovered > -0.5 and uncovered < n_win[i] + 0.5
    edge = np.empty((4, n))
    sig = np.empty((4, n))
    tex = np.empty((2, n))
    level = np.empty(n)
    end_line = np.empty(n, dtype=np.bool_)
    for r in range(n):
        hs = has_signal[r]
        for q in range(4):
            i = q * n + r
            edge[q, r] = e[i] + c0 if hs else np.nan
            sig[q, r] = math.sqrt(var[i]) if hs else np.nan
            if q < 2:
                Ls = L[i] if L[i] > 0.0 else 1.0
                tex[q, r] = (S[i] / Ls) * dlev[i] / Ls if hs else np.nan
        ok_l = ok[r]
        ok_r = ok[n + r]
        if ok_l and ok_r:
            level[r] = 0.5 * (L[r] + L[n + r])
        elif ok_l:
            level[r] = L[r]
        elif ok_r:
            level[r] = L[n + r]
        else:
            level[r] = np.nan
        end_line[r] = hs and not (ok_l and ok_r) and not spoiled[r]
    return ok, edge, sig, tex, level, end_line


@jit()
def limb_pixels(rows: np.ndarray, sgn: np.ndarray, win_first: np.ndarray, win_last: np.ndarray, n_win: np.ndarray, lev: np.ndarray, deep: np.ndarray):
    """The pixel centres of :func:`limb_levels`'s rows ``rows`` of the edges of :func:`ballscan.measure.edges._edge_pass`.

    Each row's window from its outermost pixel inwards (as many as the
    longest window of the rows: ``kw``), then its level run ``lev`` and the
    run inside it ``deep`` (box pixels, as float).

    Returns
    -------
    sg : ndarray (R,)
        The rows' sides as float (+1 left, -1 right).
    px : ndarray (R, kw + 2 n_level)
    kw : int
    """
    R = rows.shape[0]
    n_level = lev.shape[1]
    kw = 0
    for i in range(R):
        kw = max(kw, n_win[rows[i]])
    sg = np.empty(R)
    px = np.empty((R, kw + 2 * n_level))
    for i in range(R):
        r = rows[i]
        sg[i] = float(sgn[r])
        first = min(win_first[r], win_last[r]) if sg[i] > 0 else max(win_first[r], win_last[r])
        for k in range(kw):
            px[i, k] = first + sg[i] * k
        for j in range(n_level):
            px[i, kw + j] = lev[r, j]
            px[i, kw + n_level + j] = deep[r, j]
    return sg, px, kw


@jit()
def finite_rows(a: np.ndarray) -> np.ndarray:
    """``np.all(np.isfinite(a), axis=1)`` of a 2-D array (each row stops at its first non-finite value)."""
    n, w = a.shape
    out = np.ones(n, dtype=np.bool_)
    for r in range(n):
        for j in range(w):
            if not math.isfinite(a[r, j]):
                out[r] = False
                break
    return out


# ---------------------------------------------------------------------------
# Limb profile: the rows' chord samples
# ---------------------------------------------------------------------------
# LimbProfile._chords turned each line's chord samples into each row's
# offsets inwards from its edge with three gathers and two selections over
# (R, 3, n) arrays; one pass does the same subtractions.


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
