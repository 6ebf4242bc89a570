"""Edges pulled inside the silhouette by dark texture at the limb, found from the outer envelope of the edges.

Where a dark panel, a stitch or a seam of a bright ball (or a bright patch of
a dark ball) reaches the limb at the background's level, the line's edge is
read where the texture begins, up to many pixels inside the silhouette, over
runs of tens of lines (a football's panel: 3-19 px over 40-60 lines).  Such
an error only ever moves an edge *inwards*, and a run of them is smooth, so
neither the fit's symmetric outlier rejection (its robust sigma grows with
them and its model is pulled towards them) nor a line-to-line check finds
it.  Its one-sidedness does: the silhouette is the outer envelope of the
measured edges.

:func:`inward_edges` compares the edges with the averaged silhouette
(:mod:`ballscan.model.averaged`) at a first fit of all of them, lets a
quadratic in time per side absorb the pull of the contaminated runs on that
fit, and trims the edges lying inwards of that curve by more than
``k_sigma`` robust sigmas, refitting the curve to the edges kept until no
more are trimmed; outward residuals are never trimmed.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from ..geometry.camera import LineScanCamera
from ..geometry.motion import BallMotion
from ..measure.edges import EdgeMeasurements, without_edges
from ..measure.robust import median
from ..model.averaged import averaged_model
from .fit import fit_motion
from .settings import FitSettings

__all__ = ["EnvelopeSettings", "InwardEdges", "inward_edges", "largest_jump_px", "trim_inward"]


@dataclass(frozen=True)
class EnvelopeSettings:
    """Tuning of :func:`inward_edges` and :func:`trim_inward`.

    Attributes
    ----------
    k_sigma : float
        An edge inwards of the envelope by more than this many robust sigmas
        of the kept edges' residuals (and of its own sigma) is trimmed.
    floor_px : float
        Nor by less than this, pixels: the model's own error on a shaded
        limb (hundredths to a tenth of a pixel) stays below it.
    max_rounds : int
        Trimming rounds at most.
    min_lines : int
        Fewest lines with both edges for the check (a short ball has no
        envelope to speak of).
    min_chord : float
        Lines checked: the model's chord at least this share of its
        longest (the ends' edges are left to the fit).
    min_jump_px : float
        :func:`trim_inward` looks for inward edges only where an edge
        jumps: the largest second difference of a side's edges over three
        neighbouring lines of the passage's middle (:func:`largest_jump_px`)
        at least this, pixels.  A limb moves smoothly from line to line
        (second differences below a pixel on clean balls, noise included);
        a panel's border moves the edge by pixels at once.  Without a jump
        no fit is made, so a clean ball pays nothing.
    dilate_lines : int
        :func:`trim_inward` also leaves out the usable edges within this
        many lines of one it found on the same side: where a panel's border
        meets the limb the edge's error ramps up over a line or two, below
        the trimming's threshold but not the fit's noise.
    min_rms_px : float
        Nor unless the first fit of all the edges leaves them this far off
        its limb (RMS, pixels): a sphere's edges lie within tenths of a
        pixel of it, shaded and textured ones included, and a panel at the
        limb puts them pixels away.  Below it the fit's own outlier
        rejection handles the odd stitch or seam, and trimming its
        shallower neighbours would only take information away.
    envelope_weight : float
        Weight of the points inside the outer curve in its asymmetric
        least squares (the others weigh ``1 - envelope_weight``).
    """

    k_sigma: float = 3.0
    floor_px: float = 0.3
    max_rounds: int = 20
    min_lines: int = 12
    min_chord: float = 0.5
    min_jump_px: float = 2.0
    dilate_lines: int = 2
    min_rms_px: float = 2.0
    envelope_weight: float = 0.05

    def __post_init__(self) -> None:
        for name in ("k_sigma", "floor_px", "min_chord", "min_jump_px", "min_rms_px", "envelope_weight"):
            v = getattr(self, name)
            if not (isinstance(v, (int, float)) and not isinstance(v, bool) and np.isfinite(v) and v > 0):
                raise ValueError(f"EnvelopeSettings.{name}: must be a finite number > 0, got {v!r}")
        for name, lo in (("max_rounds", 1), ("min_lines", 3), ("dilate_lines", 0)):
            v = getattr(self, name)
            if not (isinstance(v, int) and not isinstance(v, bool) and v >= lo):
                raise ValueError(f"EnvelopeSettings.{name}: must be an integer >= {lo}, got {v!r}")


@dataclass(frozen=True)
class InwardEdges:
    """The edges :func:`inward_edges` trims, one flag per measured line.

    Attributes
    ----------
    left, right : ndarray of bool (N,)
        Usable edges lying inwards of the envelope.
    sigma_px : float
        Robust sigma of the kept edges about the envelope, pixels (NaN where not checked).
    """

    left: np.ndarray
    right: np.ndarray
    sigma_px: float

    @property
    def count(self) -> int:
        """Edges trimmed."""
        return int(self.left.sum() + self.right.sum())


def largest_jump_px(edges: EdgeMeasurements, min_chord: float = 0.5) -> float:
    """Largest ``|e[i+1] - 2 e[i] + e[i-1]|`` of either side's usable edges on three consecutive lines, pixels.

    Over the lines with both edges whose measured chord is at least
    ``min_chord`` of the longest (the ends' edges are steep); 0 where no
    three consecutive lines qualify.
    """
    both = edges.left_ok & edges.right_ok
    chord = np.where(both, edges.right_px - edges.left_px, np.nan)
    if not np.isfinite(chord).any():
        return 0.0
    inner = both & (chord >= min_chord * np.nanmax(chord))
    best = 0.0
    for e in (edges.left_px, edges.right_px):
        i = np.flatnonzero(inner)
        mid = i[1:-1][(i[1:-1] - i[:-2] == 1) & (i[2:] - i[1:-1] == 1)]
        if mid.size:
            best = max(best, float(np.max(np.abs(e[mid + 1] - 2.0 * e[mid] + e[mid - 1]))))
    return best


def _outer_curve(tt: np.ndarray, y: np.ndarray, use: np.ndarray, weight: float, degree: int, rounds: int = 30) -> np.ndarray:
    """A polynomial of ``degree`` in ``tt`` along the outer side of ``y[use]`` (inwards positive): asymmetric least squares.

    Points inwards of the curve weigh ``weight``, the others ``1 - weight``,
    refitted until the sides no longer change; evaluated at every ``tt``.
    """
    x, v = tt[use], y[use]
    w = np.ones(x.size)
    c = np.zeros(degree + 1)
    for _ in range(rounds):
        c = np.polyfit(x, v, degree, w=np.sqrt(w))
        new = np.where(v > np.polyval(c, x), weight, 1.0 - weight)
        if np.array_equal(new, w):
            break
        w = new
    return np.polyval(c, tt)


def inward_edges(
    camera: LineScanCamera, edges: EdgeMeasurements, motion: BallMotion, settings: EnvelopeSettings = EnvelopeSettings(), degree: int = 2
) -> InwardEdges:
    """Usable edges lying inwards of the outer envelope of a ball's edges (see the module docstring).

    Parameters
    ----------
    camera : LineScanCamera
    edges : EdgeMeasurements
        One ball's edges (pixels).
    motion : BallMotion
        A fit of the edges (a loose fit will do): the silhouette's shape
        whose residuals are enveloped.
    settings : EnvelopeSettings
    degree : int
        Degree of the polynomial in time, per side, that the envelope adds
        to the silhouette: 2 takes up the pull of a fit of every edge,
        contaminated ones included; 0 only a level, about a fit of clean
        ones (a curve's freedom there trims a side's end with the fit's
        help).
    """
    okL = edges.left_ok & np.isfinite(edges.left_px)
    okR = edges.right_ok & np.isfinite(edges.right_px)
    none = InwardEdges(np.zeros_like(okL), np.zeros_like(okR), float("nan"))
    if int(np.sum(okL & okR)) < settings.min_lines:
        return none
    me = averaged_model(camera, motion.to_params()[None, :], motion.radius_m, edges.t_s, motion.acceleration_mps2)
    resid = (edges.left_px - me.left_px[0], me.right_px[0] - edges.right_px)  # inwards positive on both sides
    # the lines well inside the passage: at the ends the chord's edges are
    # steep and spread over the exposure, and the model's error there is
    # not a texture's
    half = 0.5 * (me.right_px[0] - me.left_px[0])
    inner = np.isfinite(half) & (half >= settings.min_chord * np.nanmax(half, initial=0.0))
    okL, okR = okL & inner, okR & inner
    if int(np.sum(okL & okR)) < settings.min_lines:
        return none
    ok = (okL, okR)
    span = max(float(np.ptp(edges.t_s[okL | okR])), 1e-12)
    tt = (edges.t_s - edges.t_s[okL | okR].mean()) / span
    sig = (np.nan_to_num(edges.left_sigma_px), np.nan_to_num(edges.right_sigma_px))
    # the outer envelope first: the runs far inside it go before the
    # symmetric trimming, whose robust sigma they would otherwise widen;
    # the curve hugs the outer edges, so a clean edge lies up to its noise
    # (k_sigma of its sigma) and the model's error (a floor) inside it, and
    # twice the floor keeps those
    keep = []
    for k in range(2):
        dev = resid[k] - _outer_curve(tt, resid[k], ok[k], settings.envelope_weight, degree)
        keep.append(ok[k] & ~(dev > 2.0 * settings.floor_px + settings.k_sigma * sig[k]))
    s = float("nan")
    for _ in range(settings.max_rounds):
        # a side with too few edges left keeps them (no curve to trim about)
        dev = [
            resid[k] - np.polyval(np.polyfit(tt[keep[k]], resid[k][keep[k]], degree), tt) if keep[k].sum() > degree + 2 else np.full(tt.size, -np.inf)
            for k in range(2)
        ]
        kept_dev = np.concatenate([dev[k][keep[k] & np.isfinite(dev[k])] for k in range(2)])
        if kept_dev.size < 3:
            break
        s = 1.4826 * float(median(np.abs(kept_dev - median(kept_dev))))
        limit = [np.maximum(max(settings.k_sigma * s, settings.floor_px), settings.k_sigma * sig[k]) for k in range(2)]
        new = [keep[k] & ~(dev[k] > limit[k]) for k in range(2)]
        if all(np.array_equal(a, b) for a, b in zip(new, keep)):
            break
        keep = new
    return InwardEdges(okL & ~keep[0], okR & ~keep[1], s)


def _dilated(inward: InwardEdges, edges: EdgeMeasurements, lines: int) -> InwardEdges:
    """``inward`` with the usable edges within ``lines`` lines of a flagged one on its side flagged too."""
    if lines <= 0 or inward.count == 0:
        return inward
    k = np.ones(2 * lines + 1)
    n = inward.left.size
    grow = [np.convolve(f.astype(float), k)[lines : lines + n] > 0 for f in (inward.left, inward.right)]
    return replace(inward, left=grow[0] & edges.left_ok, right=grow[1] & edges.right_ok)


def trim_inward(
    camera: LineScanCamera,
    edges: EdgeMeasurements,
    start: BallMotion,
    fit_settings: FitSettings = FitSettings(max_reject_rounds=0, cost_tol=1e-3),
    settings: EnvelopeSettings = EnvelopeSettings(),
    passes: int = 3,
) -> InwardEdges:
    """The edges inwards of the outer envelope, about fits of the edges kept (see the module docstring).

    Each pass fits the edges kept so far (all at first) from ``start``
    (not from the last pass's fit: one pulled far along the depth velocity
    by the texture stays in that basin) with ``fit_settings`` (a loose fit
    without outlier rounds: the first one's RMS is every edge's) and finds
    :func:`inward_edges` of *all* the edges about it (a quadratic envelope
    about the first fit, a level about the others); it stops when a pass
    finds the same edges, after ``passes``, or where a fit leaves a
    parameter undetermined (the last pass's edges, none at first).  None
    are looked for where no edge jumps (``settings.min_jump_px``) or the
    first fit leaves the edges within ``settings.min_rms_px`` of its limb.
    """
    n = edges.t_s.size
    none = InwardEdges(np.zeros(n, dtype=bool), np.zeros(n, dtype=bool), float("nan"))
    if largest_jump_px(edges, settings.min_chord) < settings.min_jump_px:
        return none
    found = None
    kept = edges
    for k in range(passes):
        fit = fit_motion(camera, kept, start, fit_settings)
        if fit.undetermined or (k == 0 and not fit.residual_rms_px >= settings.min_rms_px):
            break
        # the first fit is pulled by the texture (a quadratic takes it up), the later ones are not
        degree = 2 if k == 0 else 0
        inward = _dilated(inward_edges(camera, edges, fit.motion, settings, degree), edges, settings.dilate_lines)
        if found is not None and np.array_equal(inward.left, found.left) and np.array_equal(inward.right, found.right):
            break
        found = inward
        kept = without_edges(edges, inward.left, inward.right)
    return found if found is not None else none
