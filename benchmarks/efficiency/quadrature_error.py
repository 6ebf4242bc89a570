"""The pixel model's quadrature error: coverage with n Gauss-Legendre nodes per piece against 128, and the V.x it moves (GLS at the bound's weights)."""
import sys, math
sys.path.insert(0, __import__('os').path.join(__import__('os').path.dirname(__file__), '..'))
import numpy as np
from bench_efficiency import _spec
from ballscan.lab import experiments as ex
from ballscan.solve.precision import _pixel_model

for f, v in (("radius_m", 0.11), ("speed_mps", 4.7), ("line_rate_hz", 140000.0)):
    sc = _spec(f, v, 0).scene
    cam, nse = sc.camera, sc.noise
    rows = {n: [] for n in (8, 16, 24, 32)}
    emax = {n: 0.0 for n in rows}
    for ph in np.linspace(-0.5, 0.5, 12, endpoint=False):
        m = ex.scene_geometry(sc, ph).motion
        ref, dref = _pixel_model(cam, m, 128)
        dy = sc.ball_level - sc.background_level
        y = sc.background_level + dy * ref
        var = nse.read_dn**2 + 1 / 12 + y * nse.white_dn**2 / nse.full_well_e
        G = nse.white_dn * dy * dref
        F = np.einsum("pnc,qnc->pq", G / var, G)
        C = np.linalg.inv(F)
        for n in rows:
            cn, _ = _pixel_model(cam, m, n)
            d = nse.white_dn * dy * (cn - ref)
            dth = C @ np.einsum("pnc,nc->p", G / var, d)
            rows[n].append(dth[3] / math.sqrt(C[3, 3]))
            emax[n] = max(emax[n], float(np.abs(cn - ref).max()))
    print(f"{f}={v:g}: V.x moved by the n-node coverage's error (sigma of V.x, 12 phases): " +
          "; ".join(f"n={n}: rms {np.sqrt(np.mean(np.square(r))):.3f} mean {np.mean(r):+.3f}, max pixel err {emax[n]:.4f}" for n, r in rows.items()))
