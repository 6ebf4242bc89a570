"""Is it a ball, and can its motion be right?  Flags for estimates that are numbers but not measurements.

A fit always returns numbers; these checks say when they cannot describe a
sports ball seen by a line-scan camera, so that a square of light, a radius
typed in millimetres or 8-bit samples read as 16-bit are flagged (geometry.md's
flags, marked UNRELIABLE in the table) instead of printed like any other
result.  Each check is a fixed physical or statistical bound, not a tuned
score:

``not_a_ball``
    The silhouette is not a sphere's.  The fit's reduced chi-square above
    :attr:`PlausibilityLimits.max_chi2_red` (100: the edges stray from the
    fitted sphere's limb by ten times their noise; a rendered or real ball
    gives 0.5 to 3), or a region that fills more than
    :attr:`PlausibilityLimits.max_fill` of its bounding box: a sphere's
    image (an ellipse, sheared by a velocity along the sensor, or a piece of
    one cut by an end of the image) fills at most pi/4 of its box, 0.85
    for a cut piece; a rectangle fills all of it.
``implausible_radius``
    The given radius is outside 1 mm to 0.5 m: smaller than any ball
    (a 1.5 mm airsoft BB is the smallest) or larger than any (a 0.35 m
    exercise ball); usually a radius in millimetres or centimetres where
    metres are expected.
``implausible_speed``
    Faster than :attr:`PlausibilityLimits.max_speed_mps` (150 m/s): the
    fastest measured sports projectiles are a golf ball off a long-drive
    club (103 m/s) and a badminton shuttle (137 m/s).
``implausible_range``
    The centre more than :attr:`PlausibilityLimits.max_range_m` (200 m,
    longer than any sports field) from the camera.
``wrong_bit_depth``
    The image's 16-bit values look like pairs of 8-bit samples (8-bit data
    read as 16-bit, e.g. ``watch --dtype uint16`` on an 8-bit camera's
    lines): in 8-bit data read two bytes at a time the high and low byte of
    each value are two neighbouring pixels of the scene, so they agree
    within the noise on the ball and its background alike; in real 16-bit
    data whose values spread over thousands of DN the low byte is
    independent of the high byte and agrees with it (within 8) for 17 in
    256 values.  Decided on the ball's pixels when its box's high bytes span
    at least 16 levels (a contrast of 4096 DN or more), when more than half
    of them agree.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from ..measure.detection import BallRegion
from ..measure.images import LineImage
from .results import BallEstimate

__all__ = ["PlausibilityLimits", "assess", "check_radius", "radius_problem", "RADIUS_RANGE_M"]

#: Radii (m) the estimator computes with at all: beyond them its arithmetic
#: overflows (a ball placed 1e300 m away) long before a result could mean
#: anything; between these and :class:`PlausibilityLimits`' range the
#: results are flagged ``implausible_radius``.
RADIUS_RANGE_M = (1e-6, 1e4)


@dataclass(frozen=True)
class PlausibilityLimits:
    """The bounds of :func:`assess` (see the module docstring for each one's grounds).

    Attributes
    ----------
    min_radius_m, max_radius_m : float
        A ball's radius, metres.
    max_speed_mps : float
        A sports ball's speed, m/s.
    max_range_m : float
        The ball's distance from the camera, metres.
    max_chi2_red : float
        The fit's reduced chi-square of a ball's edges.
    max_fill : float
        The fraction of its bounding box a ball's region fills.
    min_shape_px : int
        Regions of at least this many lines and pixels have their fill tested.
    min_byte_levels : int
        The high bytes' span that decides ``wrong_bit_depth``.
    byte_agreement : float
        Fraction of the ball's values whose bytes agree above which ``wrong_bit_depth`` is flagged.
    """

    min_radius_m: float = 1e-3
    max_radius_m: float = 0.5
    max_speed_mps: float = 150.0
    max_range_m: float = 200.0
    max_chi2_red: float = 100.0
    max_fill: float = 0.92
    min_shape_px: int = 8
    min_byte_levels: int = 16
    byte_agreement: float = 0.5

    def __post_init__(self) -> None:
        for name in ("min_radius_m", "max_radius_m", "max_speed_mps", "max_range_m", "max_chi2_red", "max_fill", "byte_agreement"):
            v = getattr(self, name)
            if not (isinstance(v, (int, float)) and math.isfinite(v) and v > 0):
                raise ValueError(f"PlausibilityLimits.{name}: must be a positive number, got {v!r}")
        if not self.min_radius_m < self.max_radius_m:
            raise ValueError("PlausibilityLimits: min_radius_m must be below max_radius_m")


def radius_problem(radius_m: float, limits: PlausibilityLimits = PlausibilityLimits()) -> str | None:
    """Why ``radius_m`` (metres) cannot be a ball's radius, with a hint at the unit; ``None`` when it can."""
    if limits.min_radius_m <= radius_m <= limits.max_radius_m:
        return None
    hint = ""
    if radius_m > limits.max_radius_m:
        units = [f"{radius_m:g} {unit} is {radius_m * scale:g}" for unit, scale in (("millimetres", 1e-3), ("centimetres", 1e-2)) if limits.min_radius_m <= radius_m * scale <= limits.max_radius_m]
        hint = f"; the unit is metres: {', '.join(units)}" if units else ""
    return (
        f"radius {radius_m:g} m is outside {limits.min_radius_m * 1e3:g} mm to {limits.max_radius_m:g} m, "
        f"the range of any ball{hint}"
    )


def check_radius(radius_m: float) -> float:
    """``radius_m`` as a float when the estimator can compute with it (see :data:`RADIUS_RANGE_M`).

    Raises
    ------
    ValueError
        Not a number, or outside :data:`RADIUS_RANGE_M`; the message says
        the unit is metres.
    """
    lo, hi = RADIUS_RANGE_M
    if isinstance(radius_m, bool) or not isinstance(radius_m, (int, float, np.integer, np.floating)) or not lo <= radius_m <= hi:
        raise ValueError(f"radius: {radius_m!r} m cannot be measured (need {lo:g} to {hi:g} m; the unit is metres, a ball's is 1 mm to 0.5 m)")
    return float(radius_m)


def assess(ball: BallEstimate, region: BallRegion, image: LineImage, limits: PlausibilityLimits = PlausibilityLimits()) -> BallEstimate:
    """``ball`` with the flags of every check it fails, and their reasons in ``extra["implausible"]``.

    Parameters
    ----------
    ball : BallEstimate
        The estimate of ``region``.
    region : BallRegion
        Its detected region in ``image``.
    image : LineImage
        The image (DN as stored, its bit depth).
    limits : PlausibilityLimits

    Returns
    -------
    BallEstimate
        ``ball`` itself when every check passes.
    """
    reasons: dict[str, str] = {}
    chi2 = ball.extra.get("chi2_red")
    if chi2 is not None and math.isfinite(chi2) and chi2 > limits.max_chi2_red:
        reasons["not_a_ball"] = f"the edges do not follow a sphere's silhouette (chi2_red {chi2:.3g} > {limits.max_chi2_red:g})"
    fill = _fill(region, image.width, limits)
    if fill is not None and fill > limits.max_fill:
        reasons["not_a_ball"] = f"the region fills {fill:.0%} of its box; a sphere's image fills at most 85 %"
    problem = radius_problem(ball.radius_m, limits)
    if problem is not None:
        reasons["implausible_radius"] = problem
    if ball.speed_mps is not None and ball.speed_mps > limits.max_speed_mps:
        reasons["implausible_speed"] = f"{ball.speed_mps:.4g} m/s is faster than any sports ball ({limits.max_speed_mps:g} m/s)"
    if ball.position_m is not None:
        distance = float(np.linalg.norm(ball.position_m))
        if distance > limits.max_range_m:
            reasons["implausible_range"] = f"{distance:.4g} m from the camera, farther than any sports field ({limits.max_range_m:g} m)"
    agree = _byte_agreement(region, image, limits)
    if agree is not None and agree > limits.byte_agreement:
        reasons["wrong_bit_depth"] = f"{agree:.0%} of the ball's 16-bit values are two equal bytes: 8-bit samples read as 16-bit?"
    if not reasons:
        return ball
    return replace(ball, flags=tuple(ball.flags) + tuple(reasons), extra={**ball.extra, "implausible": reasons})


def _fill(region: BallRegion, width: int, limits: PlausibilityLimits) -> float | None:
    """The fraction of its bounding box the region's mask fills; ``None`` where a sphere's image could fill it all.

    A ball cut at both its first and last line shows a band across the
    image, and one cut by both ends of the sensor a band along it: those
    fill their box whatever the object.
    """
    n_lines, n_cols = region.mask.shape
    if n_lines < limits.min_shape_px or n_cols < limits.min_shape_px:
        return None
    if "cut_first_line" in region.flags and "cut_last_line" in region.flags:
        return None
    if region.col_start == 0 and region.col_stop == width:
        return None
    return float(np.count_nonzero(region.mask)) / region.mask.size


def _byte_agreement(region: BallRegion, image: LineImage, limits: PlausibilityLimits) -> float | None:
    """The fraction of the ball's values whose high and low bytes agree within 8; ``None`` where that decides nothing.

    Only 16-bit images whose box spans at least ``limits.min_byte_levels``
    high-byte levels are tested (see the module docstring).
    """
    if image.bits != 16:
        return None
    box = image.data[region.line_start : region.line_stop, region.col_start : region.col_stop]
    values = np.asarray(box[region.mask], dtype=np.float64)
    if values.size < limits.min_shape_px or not np.all(values == np.floor(values)):
        return None
    whole = np.asarray(box, dtype=np.int64)
    if int(whole.max() // 256) - int(whole.min() // 256) < limits.min_byte_levels:
        return None
    v = values.astype(np.int64)
    return float(np.mean(np.abs(v // 256 - v % 256) <= 8))
