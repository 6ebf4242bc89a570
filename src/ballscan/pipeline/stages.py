"""The fit's stages on one detected ball.

:func:`ballscan.pipeline.estimate.estimate_region` runs them in order:

1. :func:`detect_stage`: the region's flags and its normalised box;
2. :func:`key_points_stage`: the key points and the closed-form guess of
   Eq. (3)-(7) (:mod:`ballscan.solve.initial`);
3. :func:`first_fit_stage`: the model-free edges and the motion the shading
   model is built at (the guess, or a loose fit of those edges);
4. :func:`shading_stage`: the ball's fitted Lambertian shading and limb
   profile (:mod:`ballscan.measure.shading`), the edges' levels from it, and
   whether the pixel model describes the ball;
5. :func:`pixel_fit_stage`: the requested fit of the edge windows' and the
   ends' pixels (:attr:`Recipe.pixels`);
6. :func:`second_measurement_stage`: the edges measured again with the
   shading model (matched edges, on a refined background or on the image
   with the measured column gains divided out, where the ball allows);
7. :func:`final_fit_stage`: the fit of those edges (or of the spread lines'
   pixels), and of the model-free edges where the shading path fails.

Each stage returns a frozen dataclass; :class:`StageRecord` says which path
the stages took on a ball.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, replace
from typing import Literal

import numpy as np

from ..geometry.camera import LineScanCamera
from ..geometry.motion import BallMotion
from ..measure.defocus import Defocus, estimate_defocus
from ..measure.detection import BallRegion, Detection, region_background
from ..measure.edges import EdgeMeasurements, measure_edges, with_limb, without_edges
from ..measure.matched import matched_edges
from ..measure.robust import median
from ..measure.flatfield import ColumnGains, column_gains, flat_fielded
from ..measure.images import LineImage
from ..measure.shading import LimbProfile, ShadingModel, ball_limb, shade_profile
from ..model.blur import blur_diameter
from ..solve.fit import FitResult, fit_motion
from ..solve.envelope import InwardEdges, trim_inward
from ..solve.initial import InitialGuess, find_keypoints, initial_guess
from ..solve.prior import Prior
from ..solve.settings import FitSettings
from .background import full_background, refine_background
from .recipe import Recipe

__all__ = [
    "BallInput",
    "NormalisedBox",
    "Detected",
    "FirstFit",
    "Shading",
    "PixelFit",
    "SecondMeasurement",
    "FinalFit",
    "StageRecord",
    "normalised_box",
    "shading_background",
    "unknown_gain_sigma",
    "detect_stage",
    "key_points_stage",
    "first_fit_stage",
    "shading_stage",
    "pixel_fit_stage",
    "second_measurement_stage",
    "final_fit_stage",
    "refit_with_prior",
    "stage_record",
]

#: what became of the fit's shading-aware pass
ShadingPass = Literal["off", "used", "no_start", "too_few_pixels", "not_converged"]
#: what became of the pixel fit: "off" (not asked for), "used", "spread" (the
#: spread lines' pixels after matched edges), or why the asked-for fit was not used
PixelsState = Literal["off", "used", "spread", "not_uniform", "lateral_motion", "defocus", "no_start", "no_shading_model", "not_converged"]
#: the edges the shading path's final fit takes
SecondKind = Literal["none", "window", "matched", "refined_background", "flat_fielded"]
#: the fit the estimate reports
FinalPath = Literal["pixels", "spread", "edges", "refit", "first_edges"]


@dataclass(frozen=True)
class BallInput:
    """One detected ball and what every stage measures it with.

    ``background_dn`` is the image's background at every line and pixel
    (:func:`shading_background`); ``t_lines_s`` the image lines' centre
    times, seconds; ``blind_columns`` the image columns that hold their
    neighbours' interpolation instead of the scene (stuck columns,
    :mod:`ballscan.measure.defects`): no edge is read through them.
    """

    image: LineImage
    detection: Detection
    region: BallRegion
    camera: LineScanCamera
    radius_m: float
    t_lines_s: np.ndarray
    recipe: Recipe
    background_dn: np.ndarray | None = None
    blind_columns: tuple[int, ...] = ()

    @property
    def others(self) -> list[BallRegion]:
        """The image's other balls (their pixels are kept out of this ball's edge windows)."""
        return [r for r in self.detection.regions if r.index != self.region.index]


@dataclass(frozen=True)
class NormalisedBox:
    """A ball's neighbourhood mapped to background 0, ball 1.

    Attributes
    ----------
    data : ndarray (n_lines, n_cols)
        ``polarity * (I - background) / |contrast|``.
    sigma : ndarray (n_cols,)
        Pixel noise in the same units.
    mask : ndarray of bool
        The detector's ball pixels within the box.
    line_offset, col_offset : int
        Image line and pixel of ``data[0, 0]``.
    """

    data: np.ndarray
    sigma: np.ndarray
    mask: np.ndarray
    line_offset: int
    col_offset: int


def normalised_box(image: LineImage, detection: Detection, region: BallRegion, margin: int = 3) -> NormalisedBox:
    """The region's box plus ``margin`` pixels, normalised by the measured contrast."""
    bg, noise, (ls, cs) = region_background(detection, region, margin=margin)
    contrast = abs(region.contrast_dn)
    if not contrast > 0:
        raise ValueError(f"region {region.index}: zero ball/background contrast")
    data = region.polarity * (image.data[ls, cs] - bg) / contrast
    mask = np.zeros(data.shape, dtype=bool)
    r0, c0 = region.line_start - ls.start, region.col_start - cs.start
    mask[r0 : r0 + region.mask.shape[0], c0 : c0 + region.mask.shape[1]] = region.mask
    return NormalisedBox(data=data, sigma=noise / contrast, mask=mask, line_offset=ls.start, col_offset=cs.start)


def shading_background(image: LineImage, detection: Detection, recipe: Recipe) -> np.ndarray:
    """The background every edge of the image is measured on (DN, per pixel): the detector's, or refined (``recipe.refined_background``)."""
    return full_background(refine_background(image.data, detection, recipe=recipe) if recipe.refined_background else detection)


# ------------------------------------------------------------------ 1. detect
@dataclass(frozen=True)
class Detected:
    """The region as the later stages see it: its flags (the detector's, and ``"dropped_lines"``) and its normalised box."""

    flags: tuple[str, ...]
    box: NormalisedBox


def detect_stage(ball: BallInput) -> Detected:
    """The region's flags and normalised box; ``"dropped_lines"`` where a line period within it exceeds 1.5 median periods."""
    r = ball.region
    flags = tuple(r.flags) + (("dropped_lines",) if _dropped_lines(ball.t_lines_s, r.line_start, r.line_stop - 1) else ())
    return Detected(flags=flags, box=normalised_box(ball.image, ball.detection, r))


def _dropped_lines(t: np.ndarray, first: int, last: int) -> bool:
    if t.size < 3:
        return False
    period = float(median(np.diff(t)))
    seg = np.diff(t[max(first - 1, 0) : last + 2])
    return bool(np.any(seg > 1.5 * period))


# -------------------------------------------------------------- 2. key points
def key_points_stage(ball: BallInput, detected: Detected) -> InitialGuess:
    """The key points of the normalised box and the closed-form guess of Eq. (3)-(7); ValueError where there is none.

    A ball the detector found cut by an end of the sensor (``cut_sensor_end``)
    gets the key points of the ellipse through the edges it shows.
    """
    box = detected.box
    width = ball.image.data.shape[1]
    kp = find_keypoints(
        box.data,
        box.sigma,
        box.mask,
        box.line_offset,
        box.col_offset,
        ball.t_lines_s,
        cut_first="cut_first_line" in ball.region.flags,
        cut_last="cut_last_line" in ball.region.flags,
        sensor_width_px=width if "cut_sensor_end" in ball.region.flags else None,
    )
    return initial_guess(kp, ball.camera, ball.radius_m)


# --------------------------------------------------------------- 3. first fit
@dataclass(frozen=True)
class FirstFit:
    """The model-free edges and the motion the shading model is built at.

    Attributes
    ----------
    edges : EdgeMeasurements
        The window edges on ``background_dn`` (:func:`ballscan.measure.edges.measure_edges`).
    background_dn : ndarray
        The image's background they were measured on.
    start : BallMotion or None
        The shading pass's start: the key-point guess, or the loose fit of
        ``edges`` (``Recipe.shading_start``, and always where the guess is
        degenerate); None where that loose fit failed on a degenerate guess.
    loose_fit : bool
        Whether the loose fit ran.
    time_edges_s, time_s : float
        Seconds of the edge measurement, and of the loose fits (the
        envelope's and the shading start's).
    inward : InwardEdges or None
        The edges left out as lying inwards of the edges' outer envelope
        (``Recipe.limb_envelope``; None: not looked for).
    """

    edges: EdgeMeasurements
    background_dn: np.ndarray
    start: BallMotion | None
    loose_fit: bool
    time_edges_s: float
    time_s: float
    inward: InwardEdges | None = None

    @property
    def n_inward(self) -> int:
        """Edges left out as lying inwards of the outer envelope (0 where none)."""
        return 0 if self.inward is None else self.inward.count


def first_fit_stage(ball: BallInput, guess: InitialGuess) -> FirstFit:
    """Measure the model-free edges and, for the shading pass, its start (the guess, or the loose fit of those edges).

    The shading model needs the motion only roughly (its normals and edge
    spreads barely change with a percent of speed), so the key-point guess
    will do; a degenerate one is first refined by the loose fit.
    """
    t0 = time.perf_counter()
    recipe = ball.recipe
    bg = ball.background_dn if ball.background_dn is not None else shading_background(ball.image, ball.detection, recipe)
    d = ball.detection
    edges = measure_edges(ball.image.data, ball.region, bg, d.noise_dn, ball.t_lines_s, saturation_dn=d.saturation_dn, others=ball.others, blind_columns=ball.blind_columns)
    t1 = time.perf_counter()
    inward = trim_inward(ball.camera, edges, guess.motion, recipe.loose_fit) if recipe.limb_envelope else None
    edges = _without_inward(edges, inward)
    start: BallMotion | None = guess.motion
    loose = (recipe.shading or recipe.pixels) and (guess.degenerate or recipe.shading_start == "loose_fit")
    if loose:
        first = fit_motion(ball.camera, edges, guess.motion, recipe.loose_fit)
        start = first.motion if first.converged else (None if guess.degenerate else guess.motion)
    return FirstFit(edges=edges, background_dn=bg, start=start, loose_fit=loose, time_edges_s=t1 - t0, time_s=time.perf_counter() - t1, inward=inward)


def _without_inward(edges: EdgeMeasurements, inward: InwardEdges | None) -> EdgeMeasurements:
    """``edges`` (measured on the ball's lines) without the edges ``inward`` found (:func:`ballscan.solve.envelope.trim_inward`)."""
    return without_edges(edges, inward.left, inward.right) if inward is not None and inward.count else edges


# ----------------------------------------------------------------- 4. shading
@dataclass(frozen=True)
class Shading:
    """The ball's fitted shading at the start motion.

    Attributes
    ----------
    state : {"built", "no_start", "too_few_pixels"}
        Whether the limb model was built, or why not.
    limb : LimbProfile or None
        The ball's shading law and limb profile (:func:`ballscan.measure.shading.ball_limb`).
    edges : EdgeMeasurements or None
        The first fit's window edges with their limb levels from ``limb``
        (its profile, windows and noise model reused).
    refusal : str or None
        Why the pixel model may not describe the ball (:func:`pixel_fit_refusal`), None where it does.
    defocus : Defocus or None
        The lens's blur circle the limb model carries: the camera file's, or
        measured on the ball's edges (``Recipe.defocus``); None where neither.
    time_s : float
    """

    state: Literal["built", "no_start", "too_few_pixels"]
    limb: LimbProfile | None = None
    edges: EdgeMeasurements | None = None
    refusal: str | None = None
    defocus: Defocus | None = None
    time_s: float = 0.0


def shading_stage(ball: BallInput, first: FirstFit) -> Shading:
    """The limb model at the first fit's start, the edges' limb levels from it, and the pixel model's condition.

    A Lambertian limb's brightness falls like sqrt(distance): a level taken
    inside and extrapolated linearly biases the lit side inwards.
    """
    if first.start is None:
        return Shading("no_start")
    t0 = time.perf_counter()
    recipe = ball.recipe
    limb = ball_limb(ball.camera, first.start, ball.image.data, first.edges, ball.t_lines_s, first.background_dn, level_samples=recipe.level_samples)
    if limb is None:
        return Shading("too_few_pixels", time_s=time.perf_counter() - t0)
    defocus = ball_defocus(ball, limb, first)
    if defocus is not None and defocus.source == "image" and defocus.used:
        blurred = _blurred_limb(ball, first, defocus)
        if blurred is None:
            # too few pixels inside the blurred rim for the shading law: the sharp model stands
            defocus = replace(defocus, used=False)
        limb = blurred or limb
    edges = with_limb(first.edges, limb)
    refusal = pixel_fit_refusal(limb, edges, first.start, ball.camera, recipe)
    return Shading("built", limb, edges, refusal, defocus, time.perf_counter() - t0)


def _blurred_limb(ball: BallInput, first: FirstFit, defocus: Defocus) -> LimbProfile | None:
    """The limb model again with the blur circle measured on the ball: its shading law fitted away from the blurred rim (:func:`ballscan.measure.shading.ball_limb`); the later stages take the ball's camera, with the blur, from it."""
    return ball_limb(
        replace(ball.camera, defocus_px=defocus.diameter_px), first.start, ball.image.data, first.edges, ball.t_lines_s,
        first.background_dn, level_samples=ball.recipe.level_samples,
    )


def camera_defocus(camera: LineScanCamera) -> Defocus | None:
    """The camera file's blur circle (``defocus_px``) as a :class:`Defocus` (used where it is at least :data:`ballscan.model.blur.MIN_BLUR_PX`), None without one."""
    if camera.defocus_px is None:
        return None
    return Defocus(float(camera.defocus_px), 0.0, 0, "camera", used=blur_diameter(camera) > 0)


def ball_defocus(ball: BallInput, limb: LimbProfile, first: FirstFit) -> Defocus | None:
    """The blur circle of the ball's limb model: the camera file's ``defocus_px``, else measured on its edges where ``Recipe.defocus`` asks.

    A measured blur is used only where it stands out of its own noise
    (``Recipe.defocus_min_sigmas`` of its scatter, ``Defocus.noise_px``) and reaches
    ``Recipe.defocus_min_px``: below, the blur's effect on the edges is
    below the model's other errors, and a blur that is not there would bias
    them.  None where texture at the limb was found (a panel's border widens
    the edges it crosses like a blur) or the ball is cut by the sensor's end
    (its region reaches the end: its cut side's edges are the sensor's).  An
    edge window that reaches the end while the ball does not is left out of
    the measurement like any unusable edge and does not stop it.
    """
    if ball.camera.defocus_px is not None:
        return camera_defocus(ball.camera)
    recipe = ball.recipe
    if not recipe.defocus or first.n_inward or "cut_sensor_end" in ball.region.flags:
        return None
    found = estimate_defocus(limb, first.edges)
    if found is None:
        return None
    used = found.diameter_px > 0 and found.diameter_px >= recipe.defocus_min_px and found.diameter_px > recipe.defocus_min_sigmas * found.noise_px
    return replace(found, used=bool(used))


def pixel_fit_refusal(limb: LimbProfile, edges: EdgeMeasurements, motion: BallMotion, camera: LineScanCamera, recipe: Recipe) -> str | None:
    """Why the pixel fit of the ball's ends may not be used here, or None.

    ``"not_uniform"``: the pixel model multiplies each pixel's coverage by
    one brightness per end of the ball (times the shading law's relative
    brightness), so texture or a steep limb shading bias it: the fitted
    light must stay within ``recipe.uniform_max_light`` of the contrast and
    the lines' brightness within ``recipe.uniform_max_level_rel_sigma`` of
    the law (a scatter that could not be measured, NaN, refuses).

    ``"defocus"``: the pixel model multiplies each pixel's coverage by the
    surface's brightness at the pixel, which the blur along the sensor
    mixes with its neighbours' (the window edges' limb levels move the
    whole profile, brightness and all).

    ``"lateral_motion"``: the model takes each chord position at one mean
    time of the exposure, right for the edges' mean positions and the areas
    but not for a pixel's coverage when the image also moves along the
    sensor (``vy``) by more than ``recipe.max_lateral_px`` during the
    exposure.
    """
    light = float(np.linalg.norm(limb.shading.light_dn))
    if not (light <= recipe.uniform_max_light * edges.contrast_dn and limb.level_rel_sigma <= recipe.uniform_max_level_rel_sigma):
        return "not_uniform"
    lateral_px = camera.focal_px * abs(motion.velocity_mps[1]) * camera.exposure / max(motion.position_m[2], 1e-9)
    if lateral_px > recipe.max_lateral_px:
        return "lateral_motion"
    if limb.blur_px > 0:
        return "defocus"
    return None


# --------------------------------------------------------------- 5. pixel fit
@dataclass(frozen=True)
class PixelFit:
    """The asked-for fit of the ball's edge windows' and ends' pixels (``Recipe.pixels``).

    ``state`` is "off" where it was not asked for, "used" where it
    converged (then ``fit`` is it and ``edges`` the edges it fitted, with
    the surface brightness its pixel model multiplies the coverage by), else
    why not.
    """

    state: PixelsState
    fit: FitResult | None = None
    time_s: float = 0.0
    edges: EdgeMeasurements | None = None


def pixel_fit_stage(ball: BallInput, first: FirstFit, shading: Shading) -> PixelFit:
    """Fit the pixels where ``Recipe.pixels`` asks for it and the shading model describes the ball to its pixels."""
    if not ball.recipe.pixels:
        return PixelFit("off")
    if shading.state == "no_start":
        return PixelFit("no_start")
    if shading.state == "too_few_pixels":
        return PixelFit("no_shading_model")
    if shading.refusal is not None:
        return PixelFit(shading.refusal)
    t0 = time.perf_counter()
    # the surface brightness the pixel model multiplies the coverage by
    shaded = replace(shading.edges, profile_shade=shade_profile(shading.limb, shading.edges))
    fit = fit_motion(ball.camera, shaded, first.start, ball.recipe.pixel_fit)
    if not fit.converged:
        return PixelFit("not_converged", time_s=time.perf_counter() - t0)
    return PixelFit("used", fit, time.perf_counter() - t0, shaded)


# ------------------------------------------------------ 6. second measurement
@dataclass(frozen=True)
class SecondMeasurement:
    """The edges the shading path's final fit takes.

    Attributes
    ----------
    kind : {"window", "matched", "refined_background", "flat_fielded"}
        The shading stage's window edges; matched edges on the image as it
        is, on the ball's columns' background measured away from it, or on
        the image with the ball's measured column gains divided out (and on
        that background).
    edges : EdgeMeasurements
    limb : LimbProfile
        The limb model the edges were measured with.
    column_gain_sigma : float or None
        The ball interior's relative column-gain scatter where the matched
        edges' condition measured it (NaN: too small a ball to tell).
    time_s : float
    """

    kind: SecondKind
    edges: EdgeMeasurements
    limb: LimbProfile
    column_gain_sigma: float | None = None
    time_s: float = 0.0


def second_measurement_stage(ball: BallInput, first: FirstFit, shading: Shading) -> SecondMeasurement:
    """Matched edges where the ball is uniform and ``Recipe.matched`` (the shading stage's window edges otherwise).

    On a flat-fielded sensor (the ball's interior shows at most
    ``recipe.matched_max_gain_sigma`` of column-gain scatter) the model's
    profile, fitted to each edge window, places the edge; on long balls
    (``recipe.long_ball_min_lines``) on the background of its columns
    measured away from it, as a level error common to every line moves a
    long ball's speed by several of its sigmas.  Where the interior shows
    more scatter (PRNU), with ``recipe.flat_field``, on balls with enough
    measured columns and lines, the matched edges on the image with the
    measured gains divided out (:func:`_flat_fielded_matched`); on the
    others, up to ``recipe.matched_max_prnu`` of scatter, the matched edges
    on the image as it is with their pixels' unknown gain errors in their
    sigmas (:func:`_with_gain_errors`, every gain's sigma that scatter),
    unless another ball shares its lines (:func:`_shares_lines`).
    """
    recipe = ball.recipe
    window = SecondMeasurement("window", shading.edges, shading.limb)
    if not (recipe.matched and shading.refusal is None):
        return window
    t0 = time.perf_counter()
    r, d, edges = ball.region, ball.detection, shading.edges
    gains = column_gains(ball.image.data, first.background_dn, r.mask, r.line_start, r.col_start, r.polarity, d.saturation_dn)
    sigma = gains.prnu_sigma
    long_ball = int(np.sum(edges.left_ok & edges.right_ok)) >= recipe.long_ball_min_lines
    found = None
    # NaN (a ball too small to tell) is not flat-fielded
    if math.isfinite(sigma) and sigma <= recipe.matched_max_gain_sigma:
        if long_ball:
            found = _flat_fielded_matched(ball, first, divide_gains=False)
        if found is None:
            found = _matched(edges, shading.limb)
    elif math.isfinite(sigma):
        if recipe.flat_field and gains.n_columns >= recipe.flat_field_min_columns and long_ball:
            found = _flat_fielded_matched(ball, first, divide_gains=True)
        if found is None and sigma <= recipe.matched_max_prnu and not _shares_lines(ball):
            # every column's gain unknown to the sensor's scatter (a defective column's wider sigma kept)
            spread = np.full(gains.gain.shape, sigma) if gains.gain_sigma is None else np.maximum(gains.gain_sigma, sigma)
            found = _matched(edges, shading.limb, replace(gains, gain_sigma=spread))
    return replace(found or window, column_gain_sigma=sigma, time_s=time.perf_counter() - t0)


def _matched(edges: EdgeMeasurements, limb: LimbProfile, gains: ColumnGains | None = None) -> SecondMeasurement | None:
    """The matched edges on the image as it is (their sigmas with ``gains``' errors, :func:`_with_gain_errors`), None where none matched."""
    m = matched_edges(edges, limb)
    if m is edges:
        return None
    return SecondMeasurement("matched", m if gains is None else _with_gain_errors(m, gains), limb)


def unknown_gain_sigma(column_gain_sigma: float | None, flat_fielded: bool, recipe: Recipe) -> float:
    """The relative 1-sigma of the column gains that the pixels of a ball's edges carry, 0 where they count as known.

    The scatter measured on the ball's interior
    (:func:`ballscan.measure.flatfield.column_gains`) where it exceeds what
    ``recipe`` takes for a flat-fielded sensor (``matched_max_gain_sigma``)
    and the edges were not measured with the gains divided out
    (``flat_fielded``); 0 otherwise, and where it was not measured (None,
    NaN).  The prior of the gains as nuisance parameters of a pixel fit
    (``FitSettings.pixel_gain_sigma``).
    """
    if column_gain_sigma is None or flat_fielded:
        return 0.0
    sigma = float(column_gain_sigma)
    return sigma if math.isfinite(sigma) and sigma > recipe.matched_max_gain_sigma else 0.0


def _shares_lines(ball: BallInput, margin: int = 3) -> bool:
    """Whether another ball's region comes within ``margin`` lines of this one's, whatever its columns.

    The matched path on the image as it is measures the column gains' scatter
    on the ball's interior and fits its ends' pixels with the gains as
    nuisance parameters, both for the ball alone on its lines; a ball that
    shares them keeps its window edges, which leave the other ball's pixels
    out.
    """
    r = ball.region
    return any(o.line_start < r.line_stop + margin and o.line_stop > r.line_start - margin for o in ball.others)


def _flat_fielded_matched(ball: BallInput, first: FirstFit, divide_gains: bool) -> SecondMeasurement | None:
    """Matched edges measured on the ball's columns' background away from it, with its measured column gains divided out, or None.

    Both on the background of the ball's columns measured away from it
    (:func:`ballscan.pipeline.background.refine_background`).  With
    ``divide_gains`` (a sensor whose column gains scatter, not flat-fielded)
    the gains of :func:`ballscan.measure.flatfield.column_gains` on that
    background are divided out of the ball's lines
    (:func:`ballscan.measure.flatfield.flat_fielded`), and each matched
    edge's sigma gets the gain error that remains in its edge pixel
    (:func:`_with_gain_errors`).  The edges (without those ``first`` left
    out as texture at the limb), the shading model and the matched edges
    are measured again on that image, the shading at ``first.start``.
    None where the ball then fails the pixel model's condition or no edge
    matched.
    """
    image, detection, region, recipe = ball.image, ball.detection, ball.region, ball.recipe
    bg = full_background(refine_background(image.data, detection, region, recipe=recipe))
    gains = None
    data = image.data
    if divide_gains:
        gains = column_gains(image.data, bg, region.mask, region.line_start, region.col_start, region.polarity, detection.saturation_dn)
        if not math.isfinite(gains.prnu_sigma):
            return None
        data = flat_fielded(image.data, bg, gains, region.lines, detection.saturation_dn)
    edges = measure_edges(data, region, bg, detection.noise_dn, ball.t_lines_s, saturation_dn=detection.saturation_dn, others=ball.others, blind_columns=ball.blind_columns)
    edges = _without_inward(edges, first.inward)
    start = first.start
    limb = ball_limb(ball.camera, start, data, edges, ball.t_lines_s, bg, level_samples=recipe.level_samples)
    if limb is None:
        return None
    edges = with_limb(edges, limb)
    if pixel_fit_refusal(limb, edges, start, ball.camera, recipe) is not None:
        return None
    m = matched_edges(edges, limb)
    if m is edges:
        return None
    if gains is None:
        return SecondMeasurement("refined_background", m, limb)
    return SecondMeasurement("flat_fielded", _with_gain_errors(m, gains), limb)


def _with_gain_errors(edges: EdgeMeasurements, gains: ColumnGains) -> EdgeMeasurements:
    """The matched edges' sigmas with their edge pixels' remaining column-gain error.

    An edge in pixel ``j`` covering it by ``c`` moves by about ``dg_j c``
    pixels for a gain error ``dg_j`` (:attr:`ColumnGains.gain_sigma`: the
    measurement's posterior sigma, the gains' spread where the column was
    not measured).  The error repeats on every line whose edge (same side)
    sits in that pixel, which independent sigmas would average away: each
    of those ``n_j`` lines gets ``n_j (sigma_g,j c)^2`` added to its
    variance, so that their mean carries the whole error.
    """
    out = {}
    for name, side in (("left", 1.0), ("right", -1.0)):
        flag = getattr(edges, f"{name}_matched")
        if flag is None or not flag.any():
            continue
        x = np.asarray(getattr(edges, f"{name}_px"), dtype=float)[flag]
        j = np.rint(x).astype(int)
        # covered fraction of the edge pixel (the ball inwards of the edge)
        c = np.clip(0.5 + side * (j - x), 0.0, 1.0)
        sg = np.nan_to_num(gains.residual_sigma(j))
        _, inv, count = np.unique(j, return_inverse=True, return_counts=True)
        sig = np.array(getattr(edges, f"{name}_sigma_px"), dtype=float, copy=True)
        sig[flag] = np.sqrt(sig[flag] ** 2 + count[inv] * (sg * c) ** 2)
        out[f"{name}_sigma_px"] = sig
    return replace(edges, **out) if out else edges


# --------------------------------------------------------------- 7. final fit
@dataclass(frozen=True)
class FinalFit:
    """The fit the estimate reports.

    Attributes
    ----------
    path : {"pixels", "spread", "edges", "refit", "first_edges"}
        The asked-for pixel fit; the spread lines' pixels after matched
        edges; the second measurement's edges; their refit at the fitted
        motion (``Recipe.refit_law``); or the first fit's model-free edges,
        where the shading path did not give a converged fit.
    fit : FitResult
    edges : EdgeMeasurements
        The edges fitted (on the pixel paths with the surface brightness
        the pixel model multiplies the coverage by, ``profile_shade``).
    shading : ShadingModel or None
        The shading law of the shading path's fit (None on ``"first_edges"``).
    time_attempts_s : float
        Seconds of the shading path's fits.
    time_refit_s : float
        Seconds of the refit's limb model (and of a refit not adopted).
    pixel_limb : LimbProfile or None
        On the ``"edges"`` path, where the pixel model describes the ball
        (:func:`pixel_fit_refusal` None): the limb model its edges were
        measured with, from which the pixels of their windows can be fitted
        in their place (a rig's joint fit, :mod:`ballscan.pipeline.rig`).
    settings : FitSettings
        The settings ``fit`` was made with: the recipe's for its path, with
        the column gains' prior (``pixel_gain_sigma``) on the matched path
        on the image as it is (``Recipe.matched_max_prnu``).
    """

    path: FinalPath
    fit: FitResult
    edges: EdgeMeasurements
    settings: FitSettings
    shading: ShadingModel | None = None
    time_attempts_s: float = 0.0
    time_refit_s: float = 0.0
    pixel_limb: LimbProfile | None = None


def final_fit_stage(
    ball: BallInput, guess: InitialGuess, first: FirstFit, shading: Shading | None, pixel: PixelFit, second: SecondMeasurement | None
) -> FinalFit:
    """The pixel fit where it was used, else the shading path's fit of the second measurement, else the model-free edges' fit.

    After matched edges on at least ``recipe.spread_min_lines`` lines the
    final fit takes the pixels of the ball's ends and of the lines whose
    edges spread (``recipe.spread_fit``; sharp lines keep their matched
    edges); where that does not converge, or on window edges, the edges'
    fit (``recipe.edge_fit``).  The fallback fits the first fit's edges from
    its start (with the shading pass on) or from the key-point guess.
    """
    recipe = ball.recipe
    if pixel.fit is not None and shading is not None:
        return FinalFit("pixels", pixel.fit, pixel.edges, recipe.pixel_fit, shading.limb.shading)
    t0 = time.perf_counter()
    shaded = None if second is None else _shaded_fit(ball, first, second)
    attempts_s = time.perf_counter() - t0
    if shaded is not None and shaded.fit.converged:
        uniform = shaded.path == "edges" and shading is not None and shading.refusal is None
        return replace(shaded, time_attempts_s=attempts_s, pixel_limb=second.limb if uniform else None)
    start = first.start if recipe.shading and first.start is not None else guess.motion
    fit = fit_motion(ball.camera, first.edges, start, recipe.edge_fit)
    return FinalFit("first_edges", fit, first.edges, recipe.edge_fit, None, attempts_s, 0.0 if shaded is None else shaded.time_refit_s)


def _shaded_fit(ball: BallInput, first: FirstFit, second: SecondMeasurement) -> FinalFit:
    """The shading path's fit of the second measurement (converged or not)."""
    recipe, camera = ball.recipe, ball.camera
    edges, limb = second.edges, second.limb
    if second.kind != "window" and int(np.sum(edges.left_ok & edges.right_ok)) >= recipe.spread_min_lines:
        # the narrow edges matched: the ends' and the spread edges' pixels in their place
        shaded = replace(edges, profile_shade=shade_profile(limb, edges))
        # on the image as it is, the pixels' column gains repeat on every line: nuisance parameters of their scatter
        gain = unknown_gain_sigma(second.column_gain_sigma, second.kind == "flat_fielded", recipe)
        settings = replace(recipe.spread_fit, pixel_gain_sigma=gain) if gain > 0.0 else recipe.spread_fit
        spread = fit_motion(camera, shaded, first.start, settings)
        if spread.converged:
            return FinalFit("spread", spread, shaded, settings, limb.shading)
    fit = fit_motion(camera, edges, first.start, recipe.edge_fit)
    if not (recipe.refit_law and second.kind == "window" and fit.converged):
        return FinalFit("edges", fit, edges, recipe.edge_fit, limb.shading)
    # the law and the limb model again at the fitted motion (the guess's
    # normals are a pixel or so off), and the fit
    t0 = time.perf_counter()
    limb_r = ball_limb(camera, fit.motion, ball.image.data, first.edges, ball.t_lines_s, first.background_dn, level_samples=recipe.level_samples)
    if limb_r is not None:
        edges_r = with_limb(first.edges, limb_r)
        fit_r = fit_motion(camera, edges_r, fit.motion, recipe.edge_fit)
        if fit_r.converged:
            # the adopted refit's own time is the final fit's (time_fit_s)
            return FinalFit("refit", fit_r, edges_r, recipe.edge_fit, limb_r.shading, time_refit_s=time.perf_counter() - t0 - fit_r.run_time_s)
    return FinalFit("edges", fit, edges, recipe.edge_fit, limb.shading, time_refit_s=time.perf_counter() - t0)


#: Evaluations of the repeated fit of :func:`refit_with_prior`, in multiples of the path's own.
PRIOR_REFIT_NFEV = 4


def refit_with_prior(ball: BallInput, final: FinalFit, start: BallMotion, prior: Prior) -> FitResult:
    """The final fit again, on its own edges and settings, from ``start`` with a Gaussian ``prior`` on one parameter or velocity component.

    Where the image leaves a parameter undetermined (one camera's ``vz``),
    the prior keeps it within a plausible range, so that the others are
    taken where the motion is plausible (:mod:`ballscan.solve.prior`).

    Parameters
    ----------
    ball : BallInput
        The ball's camera and recipe.
    final : FinalFit
        The fit repeated: its settings and its edges.
    start : BallMotion
        Where the repeated fit starts (s, m, m/s).
    prior : ParameterPrior or VelocityPrior

    Returns
    -------
    FitResult
        Its solver may take :data:`PRIOR_REFIT_NFEV` times the path's
        evaluations: a start held to the prior's mean lies far along the
        flat direction from the fitted motion.
    """
    settings = replace(final.settings, max_nfev=PRIOR_REFIT_NFEV * final.settings.max_nfev)
    return fit_motion(ball.camera, final.edges, start, settings, prior)


# ------------------------------------------------------------------ the record
@dataclass(frozen=True)
class StageRecord:
    """What the fit's stages did on one ball.

    Attributes
    ----------
    shading_pass : {"off", "used", "no_start", "too_few_pixels", "not_converged"}
        The shading-aware pass: off, its fit reported, or why not (no start
        motion, too few pixels for the shading model, its fit did not converge).
    pixels : {"off", "used", "spread", "not_uniform", "lateral_motion", "defocus", "no_start", "no_shading_model", "not_converged"}
        The pixel fit (:class:`PixelFit`); "spread" where the spread lines'
        pixels were fitted after matched edges without ``Recipe.pixels``.
    second_measurement : {"none", "window", "matched", "refined_background", "flat_fielded"}
        The shading path's edges (:class:`SecondMeasurement`), "none" where it did not run.
    final_fit : {"pixels", "spread", "edges", "refit", "first_edges"}
        The fit reported (:class:`FinalFit`).
    column_gain_sigma : float or None
        The ball interior's column-gain scatter where it was measured.
    flat_fielded : bool
        The reported edges are matched on the flat-fielded image.
    background_refined : bool
        The reported edges are matched on the ball's columns' background
        away from it, or every edge was (``Recipe.refined_background``).
    shading_refit : bool
        The refit at the fitted motion (``Recipe.refit_law``) is reported.
    inward_edges : int
        Model-free edges left out as lying inwards of the edges' outer
        envelope (texture at the limb, :attr:`FirstFit.n_inward`).
    defocus : Defocus or None
        The lens's blur circle: the camera file's, or the one measured on
        the ball's edges (:attr:`Shading.defocus`, ``used`` where the model
        carries it); None where neither.
    """

    shading_pass: ShadingPass
    pixels: PixelsState
    second_measurement: SecondKind
    final_fit: FinalPath
    column_gain_sigma: float | None
    flat_fielded: bool
    background_refined: bool
    shading_refit: bool
    inward_edges: int = 0
    defocus: Defocus | None = None


def stage_record(
    recipe: Recipe, camera: LineScanCamera, first: FirstFit, shading: Shading | None, pixel: PixelFit, second: SecondMeasurement | None,
    final: FinalFit,
) -> StageRecord:
    """The record of a ball's stages (``shading`` None where neither the shading pass nor the pixel fit was asked for; ``camera`` the ball's)."""
    if final.path == "first_edges":
        if shading is None or not recipe.shading:
            passed: ShadingPass = "off"
        elif shading.state != "built":
            passed = shading.state
        else:
            passed = "not_converged"
    else:
        passed = "used"
    pixels = pixel.state
    if final.path == "spread" and pixels == "off":
        pixels = "spread"
    kind = "none" if second is None else second.kind
    matched = final.edges.edges_method == "matched"
    return StageRecord(
        shading_pass=passed,
        pixels=pixels,
        second_measurement=kind,
        final_fit=final.path,
        column_gain_sigma=None if second is None else second.column_gain_sigma,
        flat_fielded=kind == "flat_fielded" and matched,
        background_refined=(kind in ("refined_background", "flat_fielded") and matched) or recipe.refined_background,
        shading_refit=final.path == "refit",
        inward_edges=first.n_inward,
        defocus=shading.defocus if shading is not None and shading.defocus is not None else camera_defocus(camera),
    )
