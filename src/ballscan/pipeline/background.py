"""The background a ball's edges are measured on, and its refinement away from the balls.

The detector's per-column level (:mod:`ballscan.measure.detection`) takes in
the pixels a ball covers by less than its mode-seeking window next to the
ball's mask, which reads the ball's edges and ends inwards; the refined
level leaves the balls' neighbourhood out.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from ..measure.detection import BallRegion, Detection, background_at
from .recipe import Recipe

__all__ = ["full_background", "refine_background"]


def refine_background(data: np.ndarray, detection: Detection, region: BallRegion | None = None, *, recipe: Recipe = Recipe()) -> Detection:
    """The detection with its balls' (or ``region``'s) columns' background levels measured away from the balls.

    The detector's per-column level (:mod:`ballscan.measure.detection`: the mean of
    a +-4.5 sigma window about the column's mode) takes in the pixels a
    ball covers by less than 4.5 sigma of the contrast, next to its mask,
    which reads the ball's edges and ends inwards and its speed high, in
    proportion to the noise.  Here each column of a region's box (plus
    ``recipe.background_guard_px``) is re-levelled from its lines outside
    every region's mask grown by ``recipe.background_guard_lines`` lines and
    ``recipe.background_guard_px`` pixels: the mean, in the detector's drift
    model, of the values within ``recipe.background_window_sigma`` noise
    sigmas of its level (two rounds); columns with fewer than
    ``recipe.background_min_lines`` such lines keep the detector's level.
    """
    if not detection.regions:
        return detection
    n, w = detection.shape
    gl, gp = recipe.background_guard_lines, recipe.background_guard_px
    c_lo = max(min(r.col_start for r in detection.regions) - gp, 0)
    c_hi = min(max(r.col_stop for r in detection.regions) + gp, w)
    near = np.zeros((n, c_hi - c_lo), dtype=bool)
    box = np.ones((2 * gl + 1, 2 * gp + 1), dtype=bool)
    for r in detection.regions:
        # the mask grown by the guard box
        from scipy.ndimage import binary_dilation  # scipy.ndimage loads with the first refined background

        grown = binary_dilation(np.pad(np.asarray(r.mask, dtype=bool), ((gl, gl), (gp, gp))), structure=box)
        l0, k0 = r.line_start - gl, r.col_start - gp - c_lo
        a0, b0 = max(l0, 0), max(k0, 0)
        a1, b1 = min(l0 + grown.shape[0], n), min(k0 + grown.shape[1], c_hi - c_lo)
        near[a0:a1, b0:b1] |= grown[a0 - l0 : a1 - l0, b0 - k0 : b1 - k0]
    cols = np.zeros(c_hi - c_lo, dtype=bool)
    for r in detection.regions if region is None else (region,):
        cols[max(r.col_start - gp, c_lo) - c_lo : min(r.col_stop + gp, c_hi) - c_lo] = True
    idx = np.flatnonzero(cols)
    x = np.asarray(data[:, c_lo:c_hi][:, idx], dtype=float)
    g = detection.line_gain[:, None]
    o = detection.line_offset_dn[:, None]
    v = (x - o) / np.where(g != 0, g, 1.0)
    far = ~near[:, idx]
    level = detection.background_dn[c_lo:c_hi][idx].astype(float)
    half = recipe.background_window_sigma * detection.noise_dn[c_lo:c_hi][idx]
    for _ in range(2):
        keep = far & (np.abs(v - level[None, :]) <= half[None, :])
        cnt = keep.sum(axis=0)
        mean = np.where(keep, v, 0.0).sum(axis=0) / np.maximum(cnt, 1)
        level = np.where(cnt >= recipe.background_min_lines, mean, level)
    b = detection.background_dn.astype(float, copy=True)
    b[c_lo + idx] = level
    return replace(detection, background_dn=b)


def full_background(detection: Detection) -> np.ndarray:
    """The detection's background (DN) at every line and pixel of its image."""
    n, w = detection.shape
    return background_at(detection, slice(0, n), slice(0, w))
