"""CRB of V.x from subsets of pixels, with the ball's brightness known or free per end."""
import sys, math
sys.path.insert(0, __import__('os').path.join(__import__('os').path.dirname(__file__), '..'))
sys.path.insert(0, __import__('os').path.dirname(__file__))
import numpy as np
from decompose import nominal_pixel_model

for f, v in (("radius_m", 0.11), ("line_rate_hz", 140000.0)):
    pm = nominal_pixel_model(f, v, 32)
    sc, m, cov, me, keep, tt, var, G = (pm[k] for k in ("scene", "motion", "cov", "me", "keep", "t", "var", "G"))
    nse = sc.noise
    L, R, sp, pres = me.left_px[0, keep], me.right_px[0, keep], np.nan_to_num(me.spread_px[0, keep]), me.presence[0, keep]
    lo = np.nanmin(L); cols = np.arange(math.floor(lo) - 2, math.floor(lo) - 2 + cov.shape[1], dtype=float)
    Gb = nse.white_dn * (sc.ball_level - sc.background_level) * cov  # brightness derivative (relative B)
    end = (tt > m.t_c_s)
    def crb(mask, bfree, nb=2):
        W = mask / var
        F = np.einsum("pnc,qnc->pq", G * W, G)
        if bfree:
            Hs = []
            for g in range(nb):
                s = (end == g)[:, None] if nb == 2 else np.ones((end.size, 1), dtype=bool)
                Hs.append(np.where(s, Gb, 0.0))
            H = np.array(Hs)
            Fgb = np.einsum("pnc,qnc->pq", G * W, H)
            Fbb = np.einsum("pnc,qnc->pq", H * W, H)
            F = F - Fgb @ np.linalg.inv(Fbb) @ Fgb.T
        return math.sqrt(np.linalg.inv(F)[3, 3])
    allm = np.ones(cov.shape)
    reach = (sp / 2 + 3.0)[:, None]
    cc = cols[None, :]
    win = (np.abs(cc - L[:, None]) <= reach) | (np.abs(cc - R[:, None]) <= reach)
    # the fit: spread lines' windows, sharp lines' (matched: the edge pixel +-2) windows, end lines all
    spread = sp >= 0.3
    sharpwin = (np.abs(cc - L[:, None]) <= 2.5) | (np.abs(cc - R[:, None]) <= 2.5)
    fitm = np.where(spread[:, None], win, sharpwin).astype(float)
    base = crb(allm, False)
    print(f"{f}={v:g}: sigma_vx all pixels, B known {base:.4g}")
    for name, mk, bf in (("all, B free per end", allm, True), ("fit's windows, B known", fitm, False), ("fit's windows, B free per end", fitm, True),
                         ("fit's windows, one B", fitm, "one")):
        s = crb(mk, bool(bf), 1 if bf == "one" else 2)
        print(f"   {name:<32} {s / base:.4f}x")
