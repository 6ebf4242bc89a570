"""Edge measurements generated from the averaged silhouette model, for tests and precision studies."""

from __future__ import annotations

import numpy as np

from ..geometry.camera import LineScanCamera
from ..geometry.motion import BallMotion
from ..measure.edges import EdgeMeasurements
from ..model.averaged import averaged_model

__all__ = ["synthetic_edges"]


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

