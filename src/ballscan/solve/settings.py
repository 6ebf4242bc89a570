"""Settings of the refinement fit (:func:`ballscan.solve.fit.fit_motion`), checked at construction."""

from __future__ import annotations

import math
import numbers
from dataclasses import dataclass, fields
from typing import Literal, get_args

__all__ = ["FitSettings"]

EdgeJacobian = Literal["analytic", "fd"]
PixelJacobian = Literal["analytic", "fd"]
PixelGroups = Literal["end", "window"]
Loss = Literal["linear", "soft_l1", "huber"]
Solver = Literal["gn", "scipy"]

# choices of the string fields
_CHOICES = {
    "pixel_jacobian": get_args(PixelJacobian),
    "pixel_groups": get_args(PixelGroups),
    "loss": get_args(Loss),
    "solver": get_args(Solver),
    "edge_jacobian": get_args(EdgeJacobian),
}
_BOOLS = (
    "fit_edge_bias", "end_line_areas", "pixels", "pixel_partial", "level_areas", "correlation_inflation",
    "area_level_partial", "broyden", "robust_first",
)
# integer fields and their least value
_INTS = {
    "pixel_nodes": 1, "level_lines": 1, "max_reject_rounds": 0, "min_edge_lines": 0, "n_nodes": 1, "max_nfev": 1,
    "jacobian_nodes": 1,
}
# real fields that must be positive (the others only non-negative)
_POSITIVE = ("f_scale", "cost_tol")
# real fields within the open interval (0, 1)
_UNIT = ("partial_shift_p",)


@dataclass(frozen=True)
class FitSettings:
    """Choices of the refinement fit of the averaged silhouette (Zhao & Wen, Eq. (7)-(10) with the dynamic sphere of Eq. (8)).

    Every field is checked at construction: a wrong type, a value out of
    range or a string outside its choices raises one :class:`ValueError`
    naming the field.

    Attributes
    ----------
    fit_edge_bias : bool
        Fit a symmetric edge bias ``b`` (pixels; left edges move by ``-b``,
        right edges by ``+b``) as a nuisance parameter.  It trades against
        ``z0``, hence off by default.
    max_spread_px : float
        Narrow-window edges are used only where the model's edge spread over
        the exposure and pixel height is below this, pixels: wider
        transitions escape the local window.
    max_spread_wide_px : float
        Lines whose model edge spread lies between ``max_spread_px`` and this
        use the wide-window edges, pixels.
    edge_floor_px : float
        Systematic 1-sigma added in quadrature to each edge sigma, pixels
        (limb shading and texture that the local level cannot follow).
    matched_floor_px : float
        The same for the edges measured by
        :func:`ballscan.measure.matched.matched_edges` (the model's own error
        on them), pixels.
    texture_gain : float
        Multiplies the edges' texture indicator, added in quadrature to each
        edge sigma (edges next to a seam get a larger sigma); dimensionless.
    end_line_areas : bool
        Fit the summed coverage of lines with signal but no usable edge pair
        (the ball's ends), where the chord grows like the square root of time.
    pixels : bool
        Fit the pixels of the ball's spread ends instead of their edges and
        areas: their ramps hold how the edge moved during the exposure
        (information on ``t_c``, ``vx``, ``vz``).  Suited to uniform balls
        and a continuous exposure; off by default.
    pixel_min_spread_px : float
        Lines whose model edge spread is below this keep their edges in the
        pixel fit, pixels.
    pixel_window_px : float
        Half-width of the pixel windows beyond half the edge spread, pixels
        (the windows must reach the ball's level on both sides).
    pixel_nodes : int
        Gauss-Legendre nodes per piece of the exposure in the pixel model
        (few nodes leave a spread edge's ramp a staircase).
    pixel_jacobian : {"analytic", "fd"}
        The pixel residuals' Jacobian: exact forward-mode derivatives in one
        compiled pass (without a known acceleration), or forward differences.
    pixel_groups : {"end", "window"}
        One free brightness per end of the ball (uniform balls) or per edge
        window (the local level: robust to texture, noisier).
    pixel_partial : bool
        Also fit the pixels of lines seen during only part of the exposure.
    pixel_floor : float
        Systematic 1-sigma of a fitted pixel's normalised value (contrast units).
    pixel_gain_sigma : float
        Relative 1-sigma of the sensor's column gains (PRNU, not
        flat-fielded), which scale the fitted pixels' ball signal alike on
        every line of a column: each column's gain is a nuisance parameter
        with this prior, eliminated (:mod:`ballscan.solve.gains`); 0: the
        gains are taken as known (a flat-fielded sensor).
    level_areas : bool
        Divide the end lines' areas by the ball's local brightness next to
        them (the median inner level of ``level_lines`` nearest lines).
    level_lines : int
        Nearest lines with a measured inner level used for it.
    reject_sigma : float
        After each fit, edges whose whitened residual exceeds this many
        robust standard deviations are rejected and the fit repeated
        (texture outliers); 0 disables the rejection.
    max_reject_rounds : int
        Rounds of rejection and refitting at most.
    correlation_inflation : bool
        Scale the covariance for the lag-one autocorrelation and the block
        means of the edge residuals: shading and seam biases are correlated
        over many lines, and treating them as independent would report too
        small a sigma.
    limb_offset_sigma_px, limb_trend_sigma_px : float
        1-sigma of a limb model error that the fit cannot see in its
        residuals, pixels: each side's edges displaced by an unknown
        constant, and by an unknown straight line and an unknown parabola
        over the passage (their values at the passage's ends), each with the
        trend's sigma.  A displacement of this shape is absorbed by the
        motion (a common trend is a ``vy``, a differing one a change of
        size, a ``vz``; a curvature the passage's duration, a ``vx``), so no
        residual-based scale reveals it; its effect on
        the parameters is added to their covariance
        (:func:`ballscan.solve.uncertainty.limb_covariance`).  0 leaves it out.
        Both are 0 by default: an error that no residual shows would widen
        the sigmas of balls whose limb the model describes exactly
        (ballscan's own renders) as much as any other's.
    limb_residual_gain : float
        The trend's and the curvature's 1-sigma grow by this many times the
        side's slowly varying residual (pixels,
        :func:`ballscan.solve.uncertainty.smooth_residual_px`): a limb whose
        model error shows in the residuals hides more in the motion.  5
        calibrates the direction angles' sigmas on the independent
        validation set's tuning half and ``vx``'s on ballscan's own seamed
        renders (docs/benchmarks.md); a clean limb's residual is white and
        adds nothing.
    area_rel_sigma : float
        Relative systematic 1-sigma of an end line's area without a
        brightness level (the lit or shaded cap's brightness is unknown);
        dimensionless.
    area_floor_px : float
        Added in quadrature to each area sigma, pixels.
    area_level_floor : float
        Relative systematic 1-sigma of the shading model's level of an end
        line, added in quadrature to the level's texture sigma; dimensionless.
    area_level_floor_px : float
        Added in quadrature to the sigma of a levelled area, pixels.
    area_level_partial : bool
        Also level the lines the ball enters or leaves during the exposure
        (their areas depend on how the exposure is sampled).
    area_partial_check : float
        Without ``area_level_partial`` (and without ``pixels``): level those
        lines anyway and keep them so only if each lies within this many
        sigma of the loose fit's model and the move between the two fits
        passes a Hausman test at ``partial_shift_p``; 0 never levels them.
    partial_shift_p : float
        False-alarm rate of that Hausman test, in (0, 1).
    loss : {"linear", "soft_l1", "huber"}
        Robust loss of the first fit with ``robust_first`` (scipy's conventions).
    f_scale : float
        Scale of the robust loss, sigmas.
    min_edge_lines : int
        Fewer lines with both edges usable (two lines with one edge count
        as one) make the fit degenerate.
    n_nodes : int
        Gauss-Legendre nodes per piece of the averaged model in the residuals.
    max_nfev : int
        Model evaluations allowed per solve.
    solver : {"gn", "scipy"}
        The built-in Levenberg-Marquardt (:func:`ballscan.solve.solver.levenberg_marquardt`)
        or :func:`scipy.optimize.least_squares` as a cross-check.
    cost_tol : float
        The built-in solver stops when the next step would lower half the
        chi-square by less than this (1e-5: a move of about 0.003 sigma).
    stall_tol : float
        A step that does not lower the cost but raises it by at most this,
        where both it and the undamped step would lower half the chi-square
        by less than this, also ends the solve (converged).
    jacobian_refresh : float
        After an accepted step that lowered half the chi-square by more than
        this (predicted), the Jacobian is recomputed; smaller steps keep the
        previous one (chord steps where the model is linear over the move).
    jacobian_nodes : int
        Gauss-Legendre nodes per piece of the model inside the
        finite-difference Jacobian (it only steers the steps and the covariance).
    broyden : bool
        Update the Jacobian by Broyden's rank-one formula between exact ones.
    edge_jacobian : {"analytic", "fd"}
        The Jacobian rows where the chord's derivative does not hold (the
        ball's ends, the area lines): the averaged model's exact
        forward-mode derivatives (without a known acceleration) or its
        forward differences.
    jacobian_reach : float
        Lines whose section offsets stay within this fraction of the radius
        get the chord model's analytic derivatives; 0 uses the averaged
        model's finite differences on every line.
    jacobian_reuse_px : float
        The finite-difference rows are recomputed only after the model's
        edges on those lines moved by more than this since they were taken,
        pixels; 0 recomputes them every time.
    robust_first : bool
        Start with a fit under the robust ``loss`` before the least-squares
        rounds with outlier rejection.
    """

    fit_edge_bias: bool = False
    max_spread_px: float = 0.3
    max_spread_wide_px: float = 0.8
    end_line_areas: bool = True
    pixel_floor: float = 0.002
    pixels: bool = False
    pixel_min_spread_px: float = 0.0
    pixel_window_px: float = 3.0
    pixel_nodes: int = 8
    pixel_jacobian: PixelJacobian = "analytic"
    pixel_groups: PixelGroups = "end"
    pixel_partial: bool = True
    pixel_gain_sigma: float = 0.0
    level_areas: bool = False
    edge_floor_px: float = 0.015
    matched_floor_px: float = 0.003
    texture_gain: float = 1.0
    level_lines: int = 3
    reject_sigma: float = 3.5
    max_reject_rounds: int = 3
    correlation_inflation: bool = True
    limb_offset_sigma_px: float = 0.0
    limb_trend_sigma_px: float = 0.0
    limb_residual_gain: float = 5.0
    area_rel_sigma: float = 3.0
    area_floor_px: float = 0.1
    area_level_floor: float = 0.002
    area_level_floor_px: float = 0.005
    area_level_partial: bool = False
    area_partial_check: float = 4.0
    partial_shift_p: float = 0.01
    loss: Loss = "soft_l1"
    f_scale: float = 3.0
    min_edge_lines: int = 5
    n_nodes: int = 3
    max_nfev: int = 60
    solver: Solver = "gn"
    cost_tol: float = 1e-5
    stall_tol: float = 1e-3
    jacobian_refresh: float = 0.1
    jacobian_nodes: int = 3
    broyden: bool = False
    robust_first: bool = False
    jacobian_reach: float = 0.8
    edge_jacobian: EdgeJacobian = "analytic"
    jacobian_reuse_px: float = 0.1

    def __post_init__(self) -> None:
        for f in fields(self):
            _check(f.name, getattr(self, f.name))


def _check(name: str, value) -> None:
    """Raise a ValueError naming ``name`` when ``value`` is not allowed for that field."""
    if name in _CHOICES:
        if value not in _CHOICES[name]:
            raise ValueError(f"FitSettings.{name}: expected one of {_CHOICES[name]}, got {value!r}")
    elif name in _BOOLS:
        if not isinstance(value, bool):
            raise ValueError(f"FitSettings.{name}: expected a bool, got {value!r}")
    elif name in _INTS:
        if isinstance(value, bool) or not isinstance(value, numbers.Integral) or value < _INTS[name]:
            raise ValueError(f"FitSettings.{name}: expected an integer >= {_INTS[name]}, got {value!r}")
    else:
        if isinstance(value, bool) or not isinstance(value, numbers.Real) or not math.isfinite(value):
            raise ValueError(f"FitSettings.{name}: expected a finite number, got {value!r}")
        if name in _UNIT and not 0.0 < value < 1.0:
            raise ValueError(f"FitSettings.{name}: expected a value in (0, 1), got {value!r}")
        if name in _POSITIVE and not value > 0.0:
            raise ValueError(f"FitSettings.{name}: expected a value > 0, got {value!r}")
        if value < 0.0:
            raise ValueError(f"FitSettings.{name}: expected a value >= 0, got {value!r}")
