"""The estimation pipeline: detection -> key points -> initial guess -> refinement.

``estimate_image`` runs the whole chain on one line-scan image and returns
an :class:`~ballscan.pipeline.results.EstimateReport` with one
:class:`~ballscan.pipeline.results.BallEstimate` per detected ball, in the order of
``t_c``.  The :class:`~ballscan.pipeline.recipe.Recipe` chooses one of two refinements:

``"paper"``
    the gradient-image matching of the paper with Powell's method
    (:mod:`ballscan.solve.paper`);
``"fit"``
    sub-pixel edges fitted by weighted nonlinear least squares with
    uncertainties (:mod:`ballscan.measure.edges`, :mod:`ballscan.solve.fit`), in two
    passes when ``shading`` is on (the default): the first fit's motion and
    the ball's fitted Lambertian shading (:mod:`ballscan.measure.shading`) give the
    profile of every edge, the edges are measured again with it and fitted
    again (the stages of :mod:`ballscan.pipeline.stages`).
"""

from __future__ import annotations

import math
import os
import time
from dataclasses import replace

import numpy as np

from ..errors import ImageFileError
from ..geometry.camera import LineScanCamera, line_times, load_camera
from ..geometry.motion import BallMotion
from ..measure.detection import BallRegion, ColumnModel, Detection, detect
from ..measure.defects import repaired_columns, repaired_image, stuck_columns
from ..measure.robust import median
from ..measure.images import LineImage, as_line_image
from ..geometry.motion import PARAM_NAMES
from ..measure.defocus import Defocus
from ..solve.derived import Transverse, psi_y
from ..solve.fit import FitResult
from ..solve.prior import VelocityPrior
from ..solve.uncertainty import MAX_VELOCITY_SIGMA_RATIO, projected, propagate, sight_axes, unfixed_across_sight, unfixed_parameters
from ..solve.initial import InitialGuess
from ..solve.paper import refine_paper
from .plausibility import assess, check_radius
from .recipe import Recipe
from .results import BallEstimate, EstimateReport
from .warmup import ensure_warm
from .stages import (
    BallInput,
    Detected,
    FinalFit,
    FirstFit,
    PixelFit,
    SecondMeasurement,
    Shading,
    StageRecord,
    detect_stage,
    final_fit_stage,
    first_fit_stage,
    key_points_stage,
    pixel_fit_stage,
    refit_with_prior,
    second_measurement_stage,
    shading_background,
    shading_stage,
    stage_record,
)

__all__ = ["estimate_image", "estimate_region"]

#: keys of an estimate that each motion parameter determines
_PARAM_KEYS = {
    "t_c_s": ("t_c_s",),
    "y0_m": ("position_m",),
    "z0_m": ("position_m",),
    "vx_mps": ("velocity_mps", "speed_mps"),
    "vy_mps": ("velocity_mps", "speed_mps"),
    "vz_mps": ("velocity_mps", "speed_mps"),
}


def estimate_region(
    image: LineImage,
    detection: Detection,
    region: BallRegion,
    camera: LineScanCamera,
    radius_m: float,
    t_lines_s: np.ndarray,
    recipe: Recipe = Recipe(),
    background_dn: np.ndarray | None = None,
    blind_columns: tuple[int, ...] = (),
) -> BallEstimate:
    """Estimate one detected ball's motion with ``recipe`` (see the module docstring).

    ``background_dn`` is the image's background at every line and pixel
    (:func:`ballscan.pipeline.stages.shading_background`); pass it when
    measuring several regions of one image so it is built once.
    ``blind_columns``: image columns repaired from their neighbours
    (:mod:`ballscan.measure.defects`), through which no edge is read.  The fit
    runs the stages of :mod:`ballscan.pipeline.stages`; the estimate's
    ``record`` (:class:`~ballscan.pipeline.stages.StageRecord`) says which
    path they took, and ``extra`` repeats it for the JSON output
    (``shading_pass``, ``pixels``, ``edges``, ``column_gain_sigma``,
    ``flat_fielded``, ``background_refined``, ``shading_refit``,
    ``inward_edges``) with the
    run times (``time_initial_s``, ``time_edges_s``, ``time_shading_s``:
    the shading pass's own, ``time_fit_s``: the reported fit's).
    """
    t0 = time.perf_counter()
    ball = BallInput(image, detection, region, camera, radius_m, t_lines_s, recipe, background_dn, tuple(blind_columns))
    detected = detect_stage(ball)
    try:
        guess = key_points_stage(ball, detected)
    except ValueError as exc:
        return BallEstimate.undetermined_estimate(
            recipe.method,
            radius_m,
            f"initial guess impossible: {exc}",
            detected.flags,
            first_line=region.line_start,
            last_line=region.line_stop - 1,
            run_time_s=time.perf_counter() - t0,
        )
    initial = _initial_estimate(guess)
    t_init = time.perf_counter() - t0
    if recipe.method == "paper":
        return _paper_estimate(ball, detected, guess, initial, t0, t_init)
    first = first_fit_stage(ball, guess)
    shading = shading_stage(ball, first) if recipe.shading or recipe.pixels else None
    if shading is not None and shading.limb is not None:
        # a blur circle measured on the ball's edges is its camera's from here on
        ball = replace(ball, camera=shading.limb.camera)
    pixel = pixel_fit_stage(ball, first, shading) if shading is not None else PixelFit("off")
    second = None
    if recipe.shading and shading is not None and shading.state == "built" and pixel.fit is None:
        second = second_measurement_stage(ball, first, shading)
    final = final_fit_stage(ball, guess, first, shading, pixel, second)
    record = stage_record(recipe, ball.camera, first, shading, pixel, second, final)
    t_shading = _shading_time(recipe, first, shading, pixel, second, final)
    flags = _guess_flags(detected, guess) + (["texture_at_limb"] if first.n_inward else [])
    flags += ["both_signs"] if "both_signs" in first.edges.flags else []
    return _fit_estimate(ball, flags, initial, guess.motion, final, record, t0, t_init, first.time_edges_s, t_shading)


def _initial_estimate(guess: InitialGuess) -> BallEstimate:
    """The key-point guess as an estimate (``BallEstimate.initial``)."""
    return BallEstimate.from_motion(
        guess.motion,
        "initial",
        flags=("initial_degenerate",) if guess.degenerate else (),
        extra={"duration_s": guess.duration_s, "depth_fallback": guess.depth_fallback, "depth_motion_sigma_m": guess.depth_motion_sigma_m},
    )


def _guess_flags(detected: Detected, guess: InitialGuess) -> list[str]:
    return list(detected.flags) + (["initial_degenerate"] if guess.degenerate else [])


def _paper_estimate(ball: BallInput, detected: Detected, guess: InitialGuess, initial: BallEstimate, t0: float, t_init: float) -> BallEstimate:
    """The paper's refinement (:func:`ballscan.solve.paper.refine_paper`) from the key-point guess."""
    box = detected.box
    res = refine_paper(ball.camera, guess.motion, box.data, box.line_offset, box.col_offset, ball.t_lines_s)
    flags = _guess_flags(detected, guess) + ([] if res.converged else ["not_converged"])
    return BallEstimate.from_motion(
        _vx_convention(res.motion, ball.camera),
        "paper",
        initial=initial,
        flags=tuple(flags),
        first_line=ball.region.line_start,
        last_line=ball.region.line_stop - 1,
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


def _shading_time(recipe: Recipe, first: FirstFit, shading: Shading | None, pixel: PixelFit, second: SecondMeasurement | None, final: FinalFit) -> float:
    """Seconds of the shading pass: its start, model and second measurement where its fit is reported, all its work where it is not."""
    if shading is None or (final.path == "first_edges" and not recipe.shading):
        return 0.0
    measured = first.time_s + shading.time_s + (second.time_s if second is not None else 0.0)
    if final.path != "first_edges":
        return measured + final.time_refit_s
    return measured + pixel.time_s + final.time_attempts_s


def _transverse(ball: BallInput, final: FinalFit, guess_motion: BallMotion, unfixed: list[str]) -> Transverse:
    """The velocity across the line of sight of a fit whose component along it alone is undetermined.

    Along the line of sight's flat direction (:func:`ballscan.solve.uncertainty.sight_axes`)
    the solver may stop anywhere, and ``vx`` follows it through their
    correlation.  The final fit is repeated, from its motion with that
    component removed and from its motion with ``vz = 0`` (the flat valley
    may hold more than one minimum; the one with fewer edges rejected, then
    the lower chi-square, is kept), under the prior ``v_sight ~ N(0, (3 |(vx, vy)|)^2)``
    (the scale beyond which a velocity component counts as undetermined,
    :data:`ballscan.solve.uncertainty.MAX_VELOCITY_SIGMA_RATIO` transverse
    speeds of the key-point guess): ``vx`` and ``v_across`` are taken where
    the depth motion is plausible (``"prior"``).  Their covariance is the
    wider, in the speed across the line of sight, of that fit's and the
    unconstrained fit's marginal one (the data's spread along the flat
    direction).  ``psi_y`` is the repeated fit's, its sigma the wider of
    the two fits' where the unconstrained one fixes ``vy`` (off the axis
    ``vy`` holds part of the flat direction, within the prior's range).
    Where the rank test finds the flat direction in ``vz`` itself, the
    pair is ``(vx, vy)``.
    Where the repeated fit does not converge, the unconstrained fit's
    ``vx``, ``v_across`` and their covariance, and its ``psi_y`` where it
    fixes ``vy`` (``"unconstrained"``).
    """
    fit = final.fit
    m = fit.motion
    if "vz_mps" in fit.undetermined:
        # the rank test found the flat direction in vz itself
        across, along = np.array([0.0, 1.0, 0.0]), np.array([0.0, 0.0, 1.0])
    else:
        across, along = sight_axes(m.position_m)
    to_pair = np.array([[1.0, 0.0, 0.0], across])
    v = np.asarray(m.velocity_mps, dtype=float)
    free = fit.covariance[3:6, 3:6]
    vx, vy, _ = guess_motion.velocity_mps
    prior = VelocityPrior(tuple(along), 0.0, MAX_VELOCITY_SIGMA_RATIO * math.hypot(vx, vy))
    fits = [refit_with_prior(ball, final, BallMotion(m.radius_m, m.t_c_s, m.position_m, tuple(u), m.acceleration_mps2), prior) for u in _prior_starts(v, along)]
    fits = [f for f in fits if f.converged and np.all(np.isfinite(f.covariance[3:6, 3:6]))]
    vy_fixed = "vy_mps" not in unfixed and np.all(np.isfinite(free[:2, :2]))
    if not fits:
        angle = psi_y(v[0], v[1], free[:2, :2]) if vy_fixed else (math.nan, math.nan)
        return Transverse(to_pair @ v, across, projected(to_pair, free), *angle, "unconstrained")
    # fewer edges rejected first: a lower chi-square on fewer edges is not a better fit
    bound = min(fits, key=lambda f: (f.n_rejected, f.chi2_red))
    held = bound.covariance[3:6, 3:6]
    vb = np.asarray(bound.motion.velocity_mps, dtype=float)
    pair, block, wide = to_pair @ vb, projected(to_pair, held), projected(to_pair, free)
    g = pair / max(float(np.linalg.norm(pair)), 1e-300)
    if np.all(np.isfinite(wide)) and g @ wide @ g > g @ block @ g:
        block = wide
    angle, angle_sigma = psi_y(vb[0], vb[1], held[:2, :2])
    if vy_fixed:
        angle_sigma = max(angle_sigma, psi_y(v[0], v[1], free[:2, :2])[1])
    return Transverse(pair, across, block, angle, angle_sigma, "prior")


def _prior_starts(v: np.ndarray, along: np.ndarray) -> list[np.ndarray]:
    """The velocities the prior's fit starts from: ``v`` less its component ``along`` the line of sight, and ``v`` with ``vz = 0`` where that differs."""
    starts = [v - (v @ along) * along]
    flat = np.array([v[0], v[1], 0.0])
    if not np.allclose(flat, starts[0]):
        starts.append(flat)
    return starts


def _along_sight_only(fit: FitResult, unfixed: list[str], guess_motion: BallMotion) -> bool:
    """Whether the velocity along the line of sight is all the fit leaves undetermined of the velocity (one camera's weak axis).

    ``vz`` is undetermined, by rank or by its sigma; ``vx`` is fixed, and
    ``vy`` is fixed too or its sigma is the line of sight's share
    (:func:`ballscan.solve.uncertainty.unfixed_across_sight`).  A ``vy``
    undetermined by rank is not taken: the rank test leaves no covariance
    to judge the velocity across the line of sight by.
    """
    velocity = {"vx_mps", "vy_mps", "vz_mps"}
    by_rank = set(fit.undetermined) & velocity
    by_sigma = set(unfixed) & velocity
    if "vz_mps" not in by_rank | by_sigma or by_rank - {"vz_mps"} or "vx_mps" in by_sigma:
        return False
    return "vy_mps" not in by_sigma or not unfixed_across_sight(fit.statistical_covariance, guess_motion, fit.motion.position_m)


def _fit_estimate(
    ball: BallInput,
    flags: list[str],
    initial: BallEstimate,
    guess_motion: BallMotion,
    final: FinalFit,
    record: StageRecord,
    t0: float,
    t_init: float,
    t_edges: float,
    t_shading: float,
) -> BallEstimate:
    """The fit's estimate: the reported fit's motion with its propagated uncertainties (:func:`ballscan.solve.uncertainty.propagate`).

    ``guess_motion`` (the key-point guess) sets the scales beyond which a
    parameter's sigma leaves it undetermined
    (:func:`ballscan.solve.uncertainty.unfixed_parameters`).  ``t0`` is the
    ball's start time (``time.perf_counter``); ``t_init``,
    ``t_edges`` and ``t_shading`` the seconds of the key points, the first
    edge measurement and the shading pass.
    """
    fit = final.fit
    flags = flags + list(fit.flags) + ([] if fit.converged else ["not_converged"])
    if record.defocus is not None and record.defocus.used:
        flags.append("defocus")
    cov = fit.covariance
    # full rank, yet not fixed by the measurements: a sigma beyond the
    # parameter's scale in the image (a cut ball's small visible part); its
    # rows are then unknown too
    unfixed = [p for p in unfixed_parameters(fit.statistical_covariance, guess_motion) if p not in fit.undetermined]
    if unfixed:
        cov = cov.copy()
        for p in unfixed:
            k = PARAM_NAMES.index(p)
            cov[k, :] = cov[:, k] = np.nan
    unc = propagate(ball.camera, fit.motion, cov)
    undetermined = sorted({k for p in (*fit.undetermined, *unfixed) for k in _PARAM_KEYS.get(p, (p,))})
    if undetermined and not (unfixed and "degenerate" in flags):
        flags.append("degenerate")

    def keep(key: str, value):
        return None if key in undetermined else value

    transverse = None
    if _along_sight_only(fit, unfixed, guess_motion):
        transverse = _transverse(ball, final, guess_motion, unfixed)

    law = final.shading
    return BallEstimate(
        method="fit",
        radius_m=ball.radius_m,
        t_c_s=keep("t_c_s", fit.motion.t_c_s),
        position_m=keep("position_m", fit.motion.position_m),
        velocity_mps=keep("velocity_mps", fit.motion.velocity_mps),
        speed_mps=keep("speed_mps", unc.speed_mps),
        t_c_sigma_s=keep("t_c_s", float(np.sqrt(cov[0, 0]))),
        position_sigma_m=keep("position_m", unc.position_sigma_m),
        velocity_sigma_mps=keep("velocity_mps", unc.velocity_sigma_mps),
        speed_sigma_mps=keep("speed_mps", unc.speed_sigma_mps),
        transverse=transverse,
        initial=initial,
        flags=tuple(flags),
        undetermined=tuple(undetermined),
        first_line=ball.region.line_start,
        last_line=ball.region.line_stop - 1,
        run_time_s=time.perf_counter() - t0,
        record=record,
        covariance=cov,
        fitted_edges=final.edges,
        pixel_limb=final.pixel_limb,
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
            "position_cov_m2": _cov_block(cov, [None, 1, 2]),
            "velocity_cov_m2ps2": cov[3:6, 3:6],
            "time_initial_s": t_init,
            "time_edges_s": t_edges,
            "time_fit_s": fit.run_time_s,
            "time_shading_s": t_shading,
            "shading_pass": record.shading_pass,
            "pixels": record.pixels,
            "edges": final.edges.edges_method,
            "column_gain_sigma": record.column_gain_sigma,
            "flat_fielded": record.flat_fielded,
            "background_refined": record.background_refined,
            "shading_refit": record.shading_refit,
            "inward_edges": record.inward_edges,
            **_defocus_keys(record.defocus),
            "shading": None
            if law is None
            else {"ambient_dn": law.ambient_dn, "light_dn": list(law.light_dn), "residual_rms_dn": law.residual_rms_dn},
        },
    )


def _defocus_keys(defocus: Defocus | None) -> dict:
    """The result's blur-circle keys (docs/geometry.md): diameter, 1-sigma (pixels), source and whether the model carries it; None where not known."""
    if defocus is None:
        return {"defocus_px": None, "defocus_sigma_px": None, "defocus_source": None, "defocus_used": False}
    return {
        "defocus_px": defocus.diameter_px, "defocus_sigma_px": defocus.sigma_px, "defocus_source": defocus.source,
        "defocus_used": defocus.used,
    }


def _cov_block(cov: np.ndarray, idx: list[int | None]) -> np.ndarray:
    """3x3 covariance of (x, y0, z0): x is 0 by definition (row/column of zeros)."""
    out = np.zeros((3, 3))
    for a, i in enumerate(idx):
        for b, j in enumerate(idx):
            if i is not None and j is not None:
                out[a, b] = cov[i, j]
    return out


def _vx_convention(motion: BallMotion, camera: LineScanCamera) -> BallMotion:
    """geometry.md: report V.x >= 0 unless the camera states the crossing direction."""
    vx = abs(motion.velocity_mps[0]) * camera.crossing_sign
    return BallMotion(motion.radius_m, motion.t_c_s, motion.position_m, (vx, *motion.velocity_mps[1:]), motion.acceleration_mps2)


def _region_estimate(image: LineImage, detection: Detection, region: BallRegion, camera: LineScanCamera, radius_m: float, t_lines_s: np.ndarray, recipe: Recipe, background_dn: np.ndarray | None, blind_columns: tuple[int, ...] = ()) -> BallEstimate:
    """:func:`estimate_region`, or an undetermined estimate saying why where its numbers fail (a region without contrast, a singular fit)."""
    t0 = time.perf_counter()
    try:
        return estimate_region(image, detection, region, camera, radius_m, t_lines_s, recipe, background_dn=background_dn, blind_columns=blind_columns)
    except (ValueError, ArithmeticError) as exc:  # numpy's LinAlgError is a ValueError
        return BallEstimate.undetermined_estimate(
            recipe.method,
            radius_m,
            f"cannot be measured: {exc}",
            tuple(region.flags),
            first_line=region.line_start,
            last_line=region.line_stop - 1,
            run_time_s=time.perf_counter() - t0,
        )


def _with_repaired(ball: BallEstimate, region: BallRegion, columns: tuple[int, ...]) -> BallEstimate:
    """``ball`` naming in ``extra["repaired_columns"]`` the repaired columns within its region's box (one column beyond it too)."""
    mine = [j for j in columns if region.col_start - 1 <= j <= region.col_stop]
    return replace(ball, extra={**ball.extra, "repaired_columns": mine}) if mine else ball


def estimate_image(
    image: LineImage | np.ndarray | str | os.PathLike[str],
    camera: LineScanCamera | str | os.PathLike[str],
    radius_m: float,
    *,
    recipe: Recipe = Recipe(),
    timestamps_s: np.ndarray | None = None,
    columns: ColumnModel | None = None,
    bits: int | None = None,
) -> EstimateReport:
    """Detect and measure every ball of one line-scan image.

    Parameters
    ----------
    image : LineImage, array (n_lines, W), or path
        The image: loaded (:func:`ballscan.measure.images.load_image`), a
        file path, or the camera's digital numbers as an array
        (:func:`ballscan.measure.images.as_line_image`; ``bits`` gives a
        float or 12-bit array's depth).
    camera : LineScanCamera or path
        The camera, or its TOML file (geometry.md).  Its width must match
        the image's.
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
    bits : int, optional
        Bits per sample of an array ``image`` (default: 8 for ``uint8``, 16
        for ``uint16``).

    Returns
    -------
    EstimateReport
        One :class:`BallEstimate` per ball found, in time order.
    """
    image = as_line_image(image, bits=bits)
    if not isinstance(camera, LineScanCamera):
        camera = load_camera(camera)
    if not isinstance(recipe, Recipe):
        raise ValueError(f"recipe: expected a Recipe, got {recipe!r}")
    radius_m = check_radius(radius_m)
    ensure_warm()  # the kernels' loading (or first compilation) is no ball's run time
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
    stuck = stuck_columns(image, det)
    if stuck.size:
        # a dead or hot column hides the ball's pixels it crosses: measured
        # again with its neighbours' interpolation in its place
        image = repaired_image(image, stuck)
        det = detect(image, columns=None if columns is None else repaired_columns(columns, stuck))
    bg = shading_background(image, det, recipe) if recipe.method == "fit" and det.regions else None
    blind = tuple(int(j) for j in stuck)
    balls = [assess(_region_estimate(image, det, r, camera, radius_m, t, recipe, bg, blind), r, image) for r in det.regions]
    balls = [_with_repaired(b, r, blind) for b, r in zip(balls, det.regions)]
    balls.sort(key=lambda b: (b.t_c_s if b.t_c_s is not None else t[min(b.first_line or 0, n_lines - 1)]))
    return EstimateReport(image=image.source, balls=tuple(balls), recipe=recipe)
