"""The estimation pipeline: detection -> key points -> initial guess -> refinement.

``estimate_image`` runs the whole chain on one line-scan image and returns
an :class:`~ballscan.pipeline.results.EstimateReport` with one
:class:`~ballscan.pipeline.results.BallEstimate` per detected ball, in the order of
``t_c``.  Two refinements are available:

``"paper"``
    the gradient-image matching of the paper with Powell's method
    (:mod:`ballscan.solve.paper`);
``"fit"``
    sub-pixel edges fitted by weighted nonlinear least squares with
    uncertainties (:mod:`ballscan.measure.edges`, :mod:`ballscan.solve.fit`), in two
    passes when ``shading`` is on (the default): the first fit's motion and
    the ball's fitted Lambertian shading (:mod:`ballscan.measure.shading`) give the
    profile of every edge, the edges are measured again with it and fitted
    again.
"""

from __future__ import annotations

import math
import numbers
import time
from dataclasses import dataclass, replace

import numpy as np
from scipy import ndimage as ndi

from ..geometry.camera import LineScanCamera, line_times
from ..measure.detection import BallRegion, ColumnModel, Detection, background_at, detect, median, region_background
from ..measure.edges import matched_edges, measure_edges, with_limb
from ..errors import ImageFileError
from ..solve.fit import FitSettings, fit_motion, propagate
from ..measure.flatfield import column_gains, flat_fielded
from ..measure.images import LineImage
from ..solve.initial import InitialGuess, find_keypoints, initial_guess
from ..geometry.motion import BallMotion
from ..solve.paper import refine_paper
from .recipe import Recipe
from .results import BallEstimate, EstimateReport
from ..measure.shading import ball_limb, shade_profile

__all__ = ["NormalisedBox", "normalised_box", "estimate_image", "estimate_region", "refine_background"]

#: keys of an estimate that each motion parameter determines
_PARAM_KEYS = {
    "t_c_s": ("t_c_s",),
    "y0_m": ("position_m",),
    "z0_m": ("position_m",),
    "vx_mps": ("velocity_mps", "speed_mps"),
    "vy_mps": ("velocity_mps", "speed_mps"),
    "vz_mps": ("velocity_mps", "speed_mps"),
}


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


def _dropped_lines(t: np.ndarray, first: int, last: int) -> bool:
    if t.size < 3:
        return False
    period = float(median(np.diff(t)))
    seg = np.diff(t[max(first - 1, 0) : last + 2])
    return bool(np.any(seg > 1.5 * period))


def _initial(box: NormalisedBox, region: BallRegion, camera: LineScanCamera, radius_m: float, t: np.ndarray) -> InitialGuess:
    kp = find_keypoints(
        box.data,
        box.sigma,
        box.mask,
        box.line_offset,
        box.col_offset,
        t,
        cut_first="cut_first_line" in region.flags,
        cut_last="cut_last_line" in region.flags,
    )
    return initial_guess(kp, camera, radius_m)


def estimate_region(
    image: LineImage,
    detection: Detection,
    region: BallRegion,
    camera: LineScanCamera,
    radius_m: float,
    t_lines_s: np.ndarray,
    recipe: Recipe = Recipe(),
    background_dn: np.ndarray | None = None,
) -> BallEstimate:
    """Estimate one detected ball's motion (see the module docstring).

    ``background_dn`` is the detector's background on the whole image
    (``background_at`` over all lines and pixels); pass it when measuring
    several regions of one image so it is built once.  ``shading`` turns the
    fit's second, shading-aware pass on (see the module docstring; a few ms
    per ball, ``extra["time_shading_s"]``; ``extra["time_fit_s"]`` is the
    final fit's).  ``pixels`` fits the pixels of the ball's edge windows and
    ends in the final fit (``pixels`` of :class:`ballscan.solve.fit.FitSettings`)
    when the ball is uniform and its image does not move along the sensor
    during the exposure (:func:`_pixel_fit_refusal`; the test needs the
    shading model, which is then fitted even with ``shading`` off but kept
    only for the pixel fit): for untextured balls and a continuous exposure.
    Where it is not used the result is that of the same call without
    ``pixels``, and ``extra["pixels"]`` says why: "off", "used", "spread" (see ``matched``),
    "not_uniform", "lateral_motion", "no_start", "no_shading_model",
    "not_converged".  ``matched`` (with the shading pass, on the same
    condition as the pixel fit) measures the narrow edges by fitting the
    shading model's profile to their windows
    (:func:`ballscan.measure.edges.matched_edges`: the edge pixel's own noise, not
    the window's and its level run's): as they are where the ball's
    interior shows no column-gain scatter
    (:func:`ballscan.measure.flatfield.column_gains`, a flat-fielded sensor), and
    with ``flat_field`` where it shows some (PRNU) on the image with the
    measured gains divided out of the ball's lines, the background of its
    columns measured away from it (:func:`refine_background`) and each
    matched edge's sigma carrying the gain error that remains
    (``extra["flat_fielded"]``; balls with at least 64 measured columns and
    250 lines with both edges: on shorter balls the window edges' sigmas
    are the honest ones, see ``_FLAT_FIELD_MIN_LINES``).  On a
    flat-fielded sensor the matched edges of balls of 250 lines or more are
    measured again on that background too (``extra["background_refined"]``,
    True also with ``flat_fielded``): the detector's level next to the
    ball is a tenth of a noise sigma high, an error common to every line,
    which on a 900-line 8-bit ball put the speed 2.4 of its sigmas high.  ``extra["edges"]`` says which
    ("window" or "matched") and ``extra["column_gain_sigma"]`` the scatter
    measured (None where the condition failed before it was measured, NaN
    where the ball is too small to measure it: then the windows are kept).  With the matched edges the
    final fit takes the pixels of the ball's ends and of the lines whose
    edges spread over 0.3 px in place of their areas and edges
    (``extra["pixels"]`` "spread"; on balls of at least 20 lines with both
    edges; the matched-edge fit where it does not converge).
    ``shading_setup`` holds the shading pass's diagnostic settings
    (:class:`ShadingSetup`; the default is the estimator described here);
    with ``refined_background`` and no ``background_dn`` the region's
    background is refined here.
    """
    method = recipe.method
    shading, pixels, matched, flat_field = recipe.shading, recipe.pixels, recipe.matched, recipe.flat_field
    t0 = time.perf_counter()
    flags = list(region.flags)
    if _dropped_lines(t_lines_s, region.line_start, region.line_stop - 1):
        flags.append("dropped_lines")
    box = normalised_box(image, detection, region)
    try:
        ig = _initial(box, region, camera, radius_m, t_lines_s)
    except ValueError as exc:
        return BallEstimate.undetermined_estimate(
            method,
            radius_m,
            f"initial guess impossible: {exc}",
            tuple(flags),
            first_line=region.line_start,
            last_line=region.line_stop - 1,
            run_time_s=time.perf_counter() - t0,
        )
    if ig.degenerate:
        flags.append("initial_degenerate")
    initial_est = BallEstimate.from_motion(
        ig.motion,
        "initial",
        flags=("initial_degenerate",) if ig.degenerate else (),
        extra={
            "duration_s": ig.duration_s,
            "depth_fallback": ig.depth_fallback,
            "depth_motion_sigma_m": ig.depth_motion_sigma_m,
        },
    )
    t_init = time.perf_counter() - t0

    if method == "paper":
        res = refine_paper(camera, ig.motion, box.data, box.line_offset, box.col_offset, t_lines_s)
        if not res.converged:
            flags.append("not_converged")
        return BallEstimate.from_motion(
            _vx_convention(res.motion, camera),
            "paper",
            initial=initial_est,
            flags=tuple(flags),
            first_line=region.line_start,
            last_line=region.line_stop - 1,
            run_time_s=time.perf_counter() - t0,
            extra={
                "energy": res.energy,
                "initial_energy": res.initial_energy,
                "evaluations": res.n_evaluations,
                "iterations": res.n_iterations,
                "time_initial_s": t_init,
                "time_refine_s": res.run_time_s,
            },
        )

    t_e = time.perf_counter()
    others = [r for r in detection.regions if r.index != region.index]
    bg_full = background_dn if background_dn is not None else _shading_background(image, detection, recipe)
    edges = measure_edges(
        image.data,
        region,
        bg_full,
        detection.noise_dn,
        t_lines_s,
        saturation_dn=detection.saturation_dn,
        others=others,
    )
    t_edges = time.perf_counter() - t_e
    shading_model = None
    t_shading = 0.0
    # what became of the second pass: "off", "used", or why it was not used
    shading_pass = "off"
    # and of the pixel fit: "off", "used", or why not
    pixels_state = "off" if not pixels else "no_start"
    # the columns' gain scatter, where the matched edges' condition measured it
    gain_sigma = None
    # whether the matched edges were measured on the crop with the measured gains divided out
    ff_used = False
    # whether they were measured on the ball's columns' background away from it (refine_background)
    bg_refined = False
    # whether ShadingSetup.refit_law's refit replaced the fit
    refit_used = False
    fit = None
    if shading or pixels:
        # The shading model needs the motion only roughly (its normals and edge
        # spreads barely change with a percent of speed): the key-point guess
        # will do; a degenerate one is first refined by a loose fit (no
        # outlier rounds, cost tolerance 1e-3).
        t_s = time.perf_counter()
        start: BallMotion | None = ig.motion
        if ig.degenerate or recipe.shading_start == "loose_fit":
            first = fit_motion(camera, edges, ig.motion, recipe.loose_fit)
            start = first.motion if first.converged else (None if ig.degenerate else ig.motion)
        shading_pass = "no_start"
        if start is not None:
            # second pass: the edges' limb levels from the ball's fitted shading
            # (a Lambertian limb's brightness falls like sqrt(distance): a level
            # taken inside and extrapolated linearly biases the lit side inwards)
            limb = ball_limb(camera, start, image.data, edges, t_lines_s, bg_full, level_samples=recipe.level_samples)
            shading_pass = "too_few_pixels"
            if pixels:
                pixels_state = "no_shading_model"
            if limb is not None:
                # the first pass's profile, windows and noise model are reused
                edges2 = with_limb(edges, limb)
                # a ball the shading law describes to its pixels (the pixel
                # fit's and the matched edges' condition)
                refusal = _pixel_fit_refusal(limb, edges2, start, camera, recipe)
                edges_fit = edges2
                t_shading = time.perf_counter() - t_s
                fit2 = None
                if pixels:
                    pixels_state = refusal or "used"
                    if pixels_state == "used":
                        # the surface brightness the pixel model multiplies the coverage by
                        shaded = replace(edges2, profile_shade=shade_profile(limb, edges2))
                        fit2 = fit_motion(camera, shaded, start, recipe.pixel_fit)
                        if not fit2.converged:
                            pixels_state, fit2 = "not_converged", None
                if fit2 is None and shading:
                    if matched and refusal is None:
                        # and a flat-fielded sensor (the model's level in every
                        # column): the model's profile, fitted to each edge
                        # window, places the edge
                        t_m = time.perf_counter()
                        gains = column_gains(image.data, bg_full, region.mask, region.line_start, region.col_start, region.polarity, detection.saturation_dn)
                        gain_sigma = gains.prnu_sigma
                        # NaN (a ball too small to tell) is not flat-fielded
                        if math.isfinite(gain_sigma) and gain_sigma <= recipe.matched_max_gain_sigma:
                            rb = None
                            if int(np.sum(edges2.left_ok & edges2.right_ok)) >= recipe.long_ball_min_lines:
                                # a long ball: measured on its columns' background
                                # away from it.  Only here: with that background
                                # on every ball the shading pass reads shaded
                                # balls' V.x low (bench_calibration, 112-268
                                # lines: mean -1.1 to -2.1 sigma; docs/benchmarks.md)
                                rb = _flat_fielded_matched(image, detection, region, t_lines_s, others, start, camera, recipe, divide_gains=False)
                            if rb is not None:
                                edges_fit, limb = rb
                                bg_refined = True
                            else:
                                edges_fit = matched_edges(edges2, limb)
                        elif (
                            flat_field
                            and math.isfinite(gain_sigma)
                            and gains.n_columns >= recipe.flat_field_min_columns
                            and int(np.sum(edges2.left_ok & edges2.right_ok)) >= recipe.long_ball_min_lines
                        ):
                            # the measured gains divided out, and the
                            # remaining gain error in the edges' sigmas
                            ff = _flat_fielded_matched(image, detection, region, t_lines_s, others, start, camera, recipe)
                            if ff is not None:
                                edges_fit, limb = ff
                                ff_used = bg_refined = True
                        t_shading += time.perf_counter() - t_m
                    if edges_fit is not edges2 and int(np.sum(edges_fit.left_ok & edges_fit.right_ok)) >= recipe.spread_min_lines:
                        # the narrow edges matched: the ends' and the spread
                        # edges' pixels in their place
                        shaded = replace(edges_fit, profile_shade=shade_profile(limb, edges_fit))
                        fit2 = fit_motion(camera, shaded, start, recipe.spread_fit)
                        if fit2.converged:
                            # (a requested pixel fit that failed keeps saying so)
                            pixels_state = "spread" if pixels_state == "off" else pixels_state
                        else:
                            fit2 = None
                    if fit2 is None:
                        fit2 = fit_motion(camera, edges_fit, start, recipe.edge_fit)
                        if recipe.refit_law and edges_fit is edges2 and fit2.converged:
                            # the law and the limb model again at the fitted motion
                            # (the guess's normals are a pixel or so off), and the fit
                            t_r = time.perf_counter()
                            limb_r = ball_limb(
                                camera, fit2.motion, image.data, edges, t_lines_s, bg_full, level_samples=recipe.level_samples
                            )
                            if limb_r is not None:
                                edges_r = with_limb(edges, limb_r)
                                fit_r = fit_motion(camera, edges_r, fit2.motion, recipe.edge_fit)
                                if fit_r.converged:
                                    fit2, edges_fit, limb, refit_used = fit_r, edges_r, limb_r, True
                            # (the adopted refit's own time is the final fit's, time_fit_s)
                            t_shading += time.perf_counter() - t_r - (fit2.run_time_s if refit_used else 0.0)
                if fit2 is not None:
                    shading_pass = "not_converged"
                    if fit2.converged:
                        edges, fit, shading_model, shading_pass = edges_fit, fit2, limb.shading, "used"
        if not shading and fit is None:
            # the shading model was fitted only for the pixel fit, which did not run
            shading_pass, t_shading = "off", 0.0
        elif fit is None:
            t_shading = time.perf_counter() - t_s
    if fit is None:
        fit = fit_motion(camera, edges, start if shading and start is not None else ig.motion, recipe.edge_fit)
    flags.extend(fit.flags)
    if not fit.converged:
        flags.append("not_converged")
    unc = propagate(camera, fit.motion, fit.covariance)
    undetermined = sorted({k for p in fit.undetermined for k in _PARAM_KEYS.get(p, (p,))})
    if undetermined:
        flags.append("degenerate")

    def keep(key: str, value):
        return None if key in undetermined else value

    cov = fit.covariance
    return BallEstimate(
        method="fit",
        radius_m=radius_m,
        t_c_s=keep("t_c_s", fit.motion.t_c_s),
        position_m=keep("position_m", fit.motion.position_m),
        velocity_mps=keep("velocity_mps", fit.motion.velocity_mps),
        speed_mps=keep("speed_mps", unc.speed_mps),
        t_c_sigma_s=keep("t_c_s", float(np.sqrt(cov[0, 0]))),
        position_sigma_m=keep("position_m", unc.position_sigma_m),
        velocity_sigma_mps=keep("velocity_mps", unc.velocity_sigma_mps),
        speed_sigma_mps=keep("speed_mps", unc.speed_sigma_mps),
        initial=initial_est,
        flags=tuple(flags),
        undetermined=tuple(undetermined),
        first_line=region.line_start,
        last_line=region.line_stop - 1,
        run_time_s=time.perf_counter() - t0,
        extra={
            "chi2_red": fit.chi2_red,
            "residual_rms_px": fit.residual_rms_px,
            "iterations": fit.n_iterations,
            "partial_levelled": fit.partial_levelled,
            "partial_verdict": fit.partial_verdict,
            "edge_bias_px": fit.edge_bias_px,
            "n_edges": fit.n_edges,
            "speed_correction_mps": unc.speed_correction_mps,
            "speed_raw_mps": unc.speed_raw_mps,
            "direction_deg": unc.direction_deg,
            "direction_sigma_deg": unc.direction_sigma_deg,
            "position_cov_m2": _cov_block(cov, [None, 1, 2]),
            "velocity_cov_m2ps2": cov[3:6, 3:6],
            "time_initial_s": t_init,
            "time_edges_s": t_edges,
            "time_fit_s": fit.run_time_s,
            "time_shading_s": t_shading,
            "shading_pass": shading_pass,
            "pixels": pixels_state,
            "edges": edges.edges_method,
            "column_gain_sigma": gain_sigma,
            "flat_fielded": ff_used and edges.edges_method == "matched",
            "background_refined": (bg_refined and edges.edges_method == "matched") or recipe.refined_background,
            "shading_refit": refit_used,
            "shading": None
            if shading_model is None
            else {
                "ambient_dn": shading_model.ambient_dn,
                "light_dn": list(shading_model.light_dn),
                "residual_rms_dn": shading_model.residual_rms_dn,
            },
        },
    )


def _shading_background(image: LineImage, detection: Detection, recipe: Recipe) -> np.ndarray:
    """The background every edge of the image is measured on (DN, per pixel): the detector's, or refined (``recipe.refined_background``)."""
    return _full_background(refine_background(image.data, detection, recipe=recipe) if recipe.refined_background else detection)


def _flat_fielded_matched(image, detection, region, t_lines_s, others, start, camera, recipe, divide_gains=True):
    """Matched edges measured on the image with the ball's measured column gains divided out, or None.

    Where the ball's interior shows column-gain scatter (PRNU, not
    flat-fielded): the gains of :func:`ballscan.measure.flatfield.column_gains`
    are divided out of the ball's lines (:func:`ballscan.measure.flatfield.flat_fielded`),
    the edges, the shading model and the matched edges are measured again
    on that image, and each matched edge's sigma gets the gain error that
    remains in its edge pixel (:func:`_with_gain_errors`).  None where the
    flat-fielded ball fails the pixel fit's condition or no edge matched.
    Both on the background of the ball's columns measured away from it
    (:func:`refine_background`).  With ``divide_gains`` False (a
    flat-fielded sensor) only that background is new: a long ball's
    edges on the detector's level read it short and narrow (the quick
    sweep's R = 0.11 m ball without PRNU, 32 seeds: speed +0.9 sigma of
    the bound on average, see ``estimate_region``).

    Returns
    -------
    (EdgeMeasurements, LimbProfile) or None
    """
    # the background of the ball's columns away from it (refine_background),
    # and the gains on that background
    bg = _full_background(refine_background(image.data, detection, region, recipe=recipe))
    if divide_gains:
        gains = column_gains(image.data, bg, region.mask, region.line_start, region.col_start, region.polarity, detection.saturation_dn)
        if not math.isfinite(gains.prnu_sigma):
            return None
        data = flat_fielded(image.data, bg, gains, region.lines, detection.saturation_dn)
    else:
        data = image.data
    edges = measure_edges(data, region, bg, detection.noise_dn, t_lines_s, saturation_dn=detection.saturation_dn, others=others)
    limb = ball_limb(camera, start, data, edges, t_lines_s, bg, level_samples=recipe.level_samples)
    if limb is None:
        return None
    edges = with_limb(edges, limb)
    if _pixel_fit_refusal(limb, edges, start, camera, recipe) is not None:
        return None
    m = matched_edges(edges, limb)
    if m is edges:
        return None
    return (_with_gain_errors(m, gains) if divide_gains else m), limb


def _with_gain_errors(edges, gains):
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


def _pixel_fit_refusal(limb, edges, motion: BallMotion, camera: LineScanCamera, recipe: Recipe) -> str | None:
    """Why the pixel fit of the ball's ends may not be used here, or None.

    ``"not_uniform"``: the pixel model multiplies each pixel's coverage by
    one brightness per end of the ball (times the shading law's relative
    brightness), so texture or a steep limb shading bias it: on a noise-free
    render of an untextured ball lit from the side (light 65 % of the
    brightness) it put V.z 8.4 m/s (3.6 sigma) off where the edges were
    within 0.5 m/s.  A flat ball with 5 DN of noise on 700 shows a light of
    0.1-0.3 % of the contrast and a level scatter of 0.2-0.7 %; a rendered
    tennis ball 5 %; a scatter that could not be measured (NaN) refuses.

    ``"lateral_motion"``: the model takes each chord position at one mean
    time of the exposure, right for the edges' mean positions and the areas
    but not for a pixel's coverage when the image also moves along the
    sensor (``vy``): at 70 deg and 80 m/s the coverage erred by up to 0.12
    of the contrast where the areas agreed to 1e-6.  On noise-free, finely
    sampled renders of the benchmark ball (30 m/s towards y) the pixel
    fit's reduced chi-square grew with that motion: 0.09, 0.22, 0.51, 4.2
    and 12 at 0.10, 0.21, 0.30, 0.42 and 0.52 px per exposure (the pixels'
    sigma there is the 0.002 floor and the detector's noise floor), its
    speed errors 0.0001 % up to 0.30 px, 0.0023 % and 0.0064 % beyond.
    """
    light = float(np.linalg.norm(limb.shading.light_dn))
    if not (light <= recipe.uniform_max_light * edges.contrast_dn and limb.level_rel_sigma <= recipe.uniform_max_level_rel_sigma):
        return "not_uniform"
    lateral_px = camera.focal_px * abs(motion.velocity_mps[1]) * camera.exposure / max(motion.position_m[2], 1e-9)
    if lateral_px > recipe.max_lateral_px:
        return "lateral_motion"
    return None


def _cov_block(cov: np.ndarray, idx: list[int | None]) -> np.ndarray:
    """3x3 covariance of (x, y0, z0): x is 0 by definition (row/column of zeros)."""
    out = np.zeros((3, 3))
    for a, i in enumerate(idx):
        for b, j in enumerate(idx):
            if i is not None and j is not None:
                out[a, b] = cov[i, j]
    return out


def refine_background(data: np.ndarray, detection: Detection, region: BallRegion | None = None, *, recipe: Recipe = Recipe()) -> Detection:
    """The detection with its balls' (or ``region``'s) columns' background levels measured away from the balls.

    The detector's per-column level (:mod:`ballscan.measure.detection`: the mean of
    a +-4.5 sigma window about the column's mode) takes in the pixels a
    ball covers by less than 4.5 sigma of the contrast, next to its mask: on
    the quick sweep's R = 0.11 m ball (8-bit, 1.8 % noise) the level of its
    columns was 0.1 sigma high, its edges and ends read inwards and the
    speed 1.5-2 sigma of the pixel bound high, in proportion to the noise
    (noise-free 0.2 sigma).  Here each column of a region's box (plus
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
        grown = ndi.binary_dilation(np.pad(np.asarray(r.mask, dtype=bool), ((gl, gl), (gp, gp))), structure=box)
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


def _full_background(detection: Detection) -> np.ndarray:
    n, w = detection.shape
    return background_at(detection, slice(0, n), slice(0, w))


def _vx_convention(motion: BallMotion, camera: LineScanCamera) -> BallMotion:
    """geometry.md: report V.x >= 0 unless the camera states the crossing direction."""
    vx = abs(motion.velocity_mps[0]) * camera.crossing_sign
    return BallMotion(motion.radius_m, motion.t_c_s, motion.position_m, (vx, *motion.velocity_mps[1:]), motion.acceleration_mps2)


def estimate_image(
    image: LineImage,
    camera: LineScanCamera,
    radius_m: float,
    *,
    recipe: Recipe = Recipe(),
    timestamps_s: np.ndarray | None = None,
    columns: ColumnModel | None = None,
) -> EstimateReport:
    """Detect and measure every ball of one line-scan image.

    Parameters
    ----------
    image : LineImage
    camera : LineScanCamera
        Its width must match the image's.
    radius_m : float
        Known ball radius, metres.
    recipe : Recipe
        The estimator's strategy (:class:`ballscan.pipeline.recipe.Recipe`).
    timestamps_s : ndarray, optional
        Per-line timestamps (seconds) replacing ``i / line_rate``.
    columns : ColumnModel, optional
        The image columns' background level and noise when they are known
        (the stream engine's, for an event's crop); else :func:`detect`
        learns them on the image.
    """
    if not isinstance(recipe, Recipe):
        raise ValueError(f"recipe: expected a Recipe, got {recipe!r}")
    if not (np.isfinite(radius_m) and radius_m > 0):
        raise ValueError(f"radius: must be positive, got {radius_m!r}")
    n_lines, width = image.data.shape
    if width != camera.width:
        raise ImageFileError(image.source, f"has {width} pixels per line but the camera file says width = {camera.width}")
    t = line_times(camera, n_lines, timestamps_s)
    if timestamps_s is not None and camera.exposure_s is None and n_lines > 1:
        # geometry.md: with per-line timestamps the exposure defaults to the
        # median line period; that period, not the file's nominal line rate,
        # is then the camera's actual rate (encoder-triggered lines)
        period = float(median(np.diff(t)))
        camera = replace(camera, line_rate_hz=1.0 / period, exposure_s=period)
    det = detect(image, columns=columns)
    bg = _shading_background(image, det, recipe) if recipe.method == "fit" and det.regions else None
    balls = [
        estimate_region(
            image, det, r, camera, radius_m, t, recipe, background_dn=bg)
        for r in det.regions
    ]
    balls.sort(key=lambda b: (b.t_c_s if b.t_c_s is not None else t[min(b.first_line or 0, n_lines - 1)]))
    return EstimateReport(image=image.source, balls=tuple(balls))
