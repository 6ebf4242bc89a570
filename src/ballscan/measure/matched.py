"""Each edge as the maximum-likelihood position of the limb model's profile.

The local area estimate of :mod:`ballscan.measure.edges` divides a window's
sum by a level measured on the line; for a uniform (untextured) ball seen by
columns of one gain the limb model supplies that level, and the whole
profile of a window around the edge is fitted by the model's profile
shifted along the line (a matched filter): :func:`matched_edges`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from .edges import EdgeMeasurements

__all__ = ["matched_edges"]

# a matched edge's last Gauss-Newton step must be below this (pixels)
_MATCHED_STEP_TOL_PX = 0.01


@dataclass(frozen=True)
class _MatchedStarts:
    """The edges :func:`matched_edges` fits, both sides in one batch.

    ``rows`` index the lines of the edges, ``sides`` is +1 (left) / -1
    (right), ``x0`` the window estimate (the start, sensor pixels) and
    ``model_edge`` the limb model's mean edge (sensor pixels).
    """

    rows: np.ndarray
    sides: np.ndarray
    x0: np.ndarray
    model_edge: np.ndarray


@dataclass(frozen=True)
class _MatchedWindows:
    """The pixels fitted for each edge of :class:`_MatchedStarts`.

    ``cols`` (sensor pixels), ``profile`` (normalised, 0 where not used)
    and ``weight`` (the window's one weight on its usable pixels, else 0),
    each ``(edges, 2 half_window_px + 1)``.
    """

    cols: np.ndarray
    profile: np.ndarray
    weight: np.ndarray


@dataclass(frozen=True)
class _MatchedFit:
    """The Gauss-Newton fit's edges (sensor pixels), their 1-sigma (pixels) and its last step (pixels)."""

    edge_px: np.ndarray
    sigma_px: np.ndarray
    last_step_px: np.ndarray


def _matched_starts(edges: EdgeMeasurements, limb: Any, max_spread_px: float) -> _MatchedStarts:
    """The usable narrow-window edges of lines whose model edge spread is at most ``max_spread_px``."""
    lines = edges.lines
    spread = np.asarray(limb.spread_px)[lines]
    # both sides in one batch (the limb model caches its samples per batch)
    rows, sides, x0, model_edge = [], [], [], []
    for side, start, ok, model in ((1.0, edges.left_px, edges.left_ok, limb.left_px), (-1.0, edges.right_px, edges.right_ok, limb.right_px)):
        model = np.asarray(model)[lines]
        use = np.flatnonzero(ok & np.isfinite(start) & np.isfinite(model) & (spread <= max_spread_px))
        rows.append(use)
        sides.append(np.full(use.size, side))
        x0.append(start[use])
        model_edge.append(model[use])
    return _MatchedStarts(rows=np.concatenate(rows), sides=np.concatenate(sides), x0=np.concatenate(x0), model_edge=np.concatenate(model_edge))


def _matched_windows(edges: EdgeMeasurements, st: _MatchedStarts, half_window_px: int) -> _MatchedWindows:
    """The profile's pixels around each starting edge and one weight per window (see :func:`matched_edges`)."""
    rows = st.rows
    c0 = edges.profile_col0
    n_cols = edges.profile.shape[1]
    h = int(half_window_px)
    cols = np.rint(st.x0).astype(int)[:, None] + np.arange(-h, h + 1)[None, :]
    inside = (cols >= c0) & (cols < c0 + n_cols)
    ci = np.clip(cols - c0, 0, n_cols - 1)
    p = edges.profile[rows[:, None], ci]
    sig = edges.profile_sigma[rows[:, None], ci]
    good = inside & np.isfinite(p) & np.isfinite(sig) & (sig > 0)
    # one weight per window: the inverse of its pixels' mean variance
    n_good = good.sum(axis=1)
    var = np.where(good, sig, 0.0) ** 2
    w_row = np.where(n_good > 0, n_good / np.where(n_good > 0, var.sum(axis=1), 1.0), 0.0)
    w = np.where(good, w_row[:, None], 0.0)
    p = np.where(good, p, 0.0)
    return _MatchedWindows(cols=cols, profile=p, weight=w)


def _matched_fit(limb: Any, img_lines: np.ndarray, st: _MatchedStarts, win: _MatchedWindows, rounds: int, step_px: float) -> _MatchedFit:
    """``rounds`` Gauss-Newton steps of the model's shift along the line (each at most half a pixel)."""
    sides, model_edge, w, p = st.sides, st.model_edge, win.weight, win.profile
    # pixel centres' offsets from the model's edge, positive inwards
    off_model = sides[:, None] * (win.cols - model_edge[:, None])
    shift = st.x0 - model_edge
    info = np.zeros(st.rows.size)
    move = np.full(st.rows.size, np.inf)
    dstep = np.array([-step_px, 0.0, step_px])
    for _ in range(int(rounds)):
        off = off_model - sides[:, None] * shift[:, None]
        # the surface brightness barely changes over the shifts of one step
        bright = np.nan_to_num(limb.surface(img_lines, sides, off))
        v = [bright * np.nan_to_num(limb.pixel_coverage(img_lines, sides, off - sides[:, None] * ds)) for ds in dstep]
        g = (v[2] - v[0]) / (2.0 * step_px)
        info = (w * g * g).sum(axis=1)
        has = info > 0
        move = np.where(has, (w * g * (p - v[1])).sum(axis=1) / np.where(has, info, 1.0), 0.0)
        shift = shift + np.clip(move, -0.5, 0.5)
    x = model_edge + shift
    s = np.where(info > 0, 1.0 / np.sqrt(np.where(info > 0, info, 1.0)), np.nan)
    return _MatchedFit(edge_px=x, sigma_px=s, last_step_px=move)


def _with_matched(edges: EdgeMeasurements, st: _MatchedStarts, fit: _MatchedFit, done: np.ndarray) -> EdgeMeasurements:
    """``edges`` with the converged matched edges (``done``) in place of the window estimates, flagged as matched."""
    changes = {}
    for side, name in ((1.0, "left"), (-1.0, "right")):
        sel = (st.sides == side) & done
        for field_name, val in ((f"{name}_px", fit.edge_px[sel]), (f"{name}_sigma_px", fit.sigma_px[sel])):
            a = np.array(getattr(edges, field_name), dtype=float, copy=True)
            a[st.rows[sel]] = val
            changes[field_name] = a
        flag = np.zeros(edges.lines.size, dtype=bool)
        flag[st.rows[sel]] = True
        changes[f"{name}_matched"] = flag
    return replace(edges, **changes)


def matched_edges(
    edges: EdgeMeasurements,
    limb: Any,
    *,
    max_spread_px: float = 0.3,
    half_window_px: int = 3,
    rounds: int = 2,
    step_px: float = 0.05,
) -> EdgeMeasurements:
    """Each edge as the maximum-likelihood position of the limb model's profile (uniform balls).

    The local area estimate (:func:`measure_edges`) sums a window of three
    or more pixels and divides by a level measured on two more: on a sharp
    edge only the one partly covered pixel says where the edge is, and the
    others add their noise (on a flat ball the window's error is nearly
    twice the edge pixel's own noise).  Here the whole profile of
    the window, ``half_window_px`` pixels either side of the edge, is
    fitted by the model's normalised values, the shading law's surface
    brightness times each whole pixel's coverage by the averaged silhouette
    (:meth:`ballscan.measure.shading.LimbProfile.pixel_coverage`), shifted along the
    line: ``rounds`` Gauss-Newton steps in the shift, so a pixel counts by
    how much its coverage changes with the edge (matched filter); one
    weight per window, the inverse of its pixels' mean variance (weights
    that follow each pixel's noise estimate, which grows with the measured
    value, would correlate with the noise itself).  The narrow edges' error
    then comes close to the edge pixel's noise, and the estimate is unbiased
    on noise-free renders.

    The level comes from the model, not from the line: only for a ball the
    law describes to its pixels (untextured) seen by a sensor whose columns
    share one gain (flat-fielded; see
    :func:`ballscan.pipeline.estimate.estimate_region` and
    :mod:`ballscan.measure.flatfield`), where the local level's noise is the price
    of robustness that buys nothing.

    Parameters
    ----------
    edges : EdgeMeasurements
        From :func:`measure_edges` or :func:`with_limb` (the profile and its
        noise are used; the edges are the starting points).
    limb : LimbProfile
        The ball's profile model (:func:`ballscan.measure.shading.ball_limb`).
    max_spread_px : float
        Only the narrow-window edges (``left_px``, ``right_px``) of lines
        whose model edge spread is at most this are measured: the fit's
        ``FitSettings.max_spread_px`` (0.3), beyond which it reads the wide
        window's fields, which are kept.  The spread edges (0.3-0.8 px) are
        not matched: their inner pixels would carry the model's level, which
        biases the speed of small balls of 8-bit images.  ``>= 0``.
    half_window_px : int
        Pixels on either side of the starting edge's pixel that are fitted,
        ``>= 1``.
    rounds : int
        Gauss-Newton steps (each at most half a pixel), ``>= 1``.
    step_px : float
        Shift of the central differences of the model's profile, pixels,
        ``> 0``.

    Returns
    -------
    EdgeMeasurements
        ``left_px``, ``right_px`` and their sigmas replaced where the fit
        converged (its last step below 0.01 px, within 0.5 px of the window
        estimate), ``left_matched`` / ``right_matched`` True there; usable
        flags and the wide-window fields unchanged; the input itself where
        no edge converged.

    Raises
    ------
    ValueError
        If a setting is out of its range (the message names it), or
        ``edges`` has no profile.
    """
    if not (isinstance(max_spread_px, (int, float)) and max_spread_px >= 0):
        raise ValueError(f"max_spread_px: must be a number >= 0, got {max_spread_px!r}")
    if not (isinstance(half_window_px, (int, np.integer)) and half_window_px >= 1):
        raise ValueError(f"half_window_px: must be an integer >= 1, got {half_window_px!r}")
    if not (isinstance(rounds, (int, np.integer)) and rounds >= 1):
        raise ValueError(f"rounds: must be an integer >= 1, got {rounds!r}")
    if not (isinstance(step_px, (int, float)) and math.isfinite(step_px) and step_px > 0):
        raise ValueError(f"step_px: must be a finite number > 0, got {step_px!r}")
    if edges.profile is None or edges.profile_sigma is None:
        raise ValueError("edges: no profile to fit (made by measure_edges?)")
    st = _matched_starts(edges, limb, max_spread_px)
    if st.rows.size == 0:
        return edges
    win = _matched_windows(edges, st, half_window_px)
    fit = _matched_fit(limb, edges.lines[st.rows], st, win, rounds, step_px)
    # converged (the last step is a few thousandths of a pixel on clean
    # data) and near the window estimate; else the window's value stays
    x = fit.edge_px
    done = np.isfinite(x) & np.isfinite(fit.sigma_px) & (np.abs(fit.last_step_px) < _MATCHED_STEP_TOL_PX) & (np.abs(x - st.x0) < 0.5)
    if not done.any():
        return edges
    return _with_matched(edges, st, fit, done)
