"""The lens's blur circle: its marginals, its measurement on a ball's edges and its place in the limb and silhouette models."""

from __future__ import annotations

import json
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from ballscan.geometry.camera import LineScanCamera, camera_from_dict
from ballscan.geometry.motion import BallMotion
from ballscan.errors import CameraFileError
from ballscan.measure.defocus import DefocusSettings, blur_kernel
from ballscan.model.blur import semicircle_nodes
from ballscan.model.averaged import averaged_model, blur_offsets
from ballscan.model.render import Appearance, render
from ballscan.pipeline.estimate import estimate_image

ROOT = Path(__file__).resolve().parents[1]
CAM = LineScanCamera(width=400, focal_px=2500.0, principal_px=200.0, line_rate_hz=20000.0, exposure_s=2e-5)


# ------------------------------------------------------------------ the blur circle's marginal
@pytest.mark.parametrize("diameter", [0.6, 1.0, 2.5, 4.0])
def test_kernel_is_the_semicircle_with_its_variance(diameter):
    step = 0.01
    k = blur_kernel(diameter, step)
    x = (np.arange(k.size) - (k.size - 1) / 2) * step
    assert k.sum() == pytest.approx(1.0) and np.allclose(k, k[::-1])
    # a uniform disc of radius a has the variance a^2 / 4 along either axis
    assert (k * x * x).sum() == pytest.approx((diameter / 2) ** 2 / 4, rel=2e-3)


def test_kernel_below_half_a_cell_is_the_identity():
    assert np.array_equal(blur_kernel(0.04, 0.1), [1.0])


@pytest.mark.parametrize("n", [4, 8, 12])
def test_nodes_integrate_the_semicircles_moments(n):
    s, w = semicircle_nodes(3.0, n)
    a = 1.5
    assert w.sum() == pytest.approx(1.0) and (w @ s) == pytest.approx(0.0, abs=1e-12)
    assert (w @ s**2) == pytest.approx(a**2 / 4)
    assert (w @ s**4) == pytest.approx(a**4 / 8)
    # in focus: one offset 0 of weight 1
    assert [list(v) for v in semicircle_nodes(0.0, n)] == [[0.0], [1.0]]


# ------------------------------------------------------------------ the edges' least squares
def _edge_squares_numpy(point, kernel, below, fraction, y, w):
    """The kernel's result as whole-array numpy: every row convolved (np.convolve, centred), every shift's level and squares."""
    k = kernel.size
    c = (k - 1) // 2
    full = np.array([np.convolve(row, kernel) for row in point])
    model = full[:, c:c + point.shape[1]]
    if k % 2 == 0:
        model = 0.5 * (model + full[:, c + 1:c + 1 + point.shape[1]])
    e = np.arange(point.shape[0])[:, None, None]
    m = model[e, below] + (model[e, below + 1] - model[e, below]) * fraction
    y, w = y[:, None], w[:, None]
    level = (m * w * y).sum(-1) / (m * w * m).sum(-1)
    return (w * (y - level[..., None] * m) ** 2).sum(-1).min(axis=1)


@pytest.mark.parametrize("n_kernel", [1, 6, 11, 40])
def test_edge_squares_are_the_whole_array_formulation(n_kernel):
    from ballscan.measure._defocus_kernels import edge_squares

    rng = np.random.default_rng(n_kernel)
    n_edge, n_grid, n_shift, n_pix = 7, 120, 5, 11
    point = np.cumsum(rng.random((n_edge, n_grid)), axis=1) / n_grid
    kernel = rng.random(n_kernel)
    kernel /= kernel.sum()
    below = rng.integers(0, n_grid - 1, (n_edge, n_shift, n_pix))
    below[0, 0, 0] = n_grid - 2  # the last pair of samples, where the convolution meets the row's end
    below[1, 0, 0] = 0  # and the first pair, where it meets its start
    fraction = rng.random((n_edge, n_shift, n_pix))
    y = rng.random((n_edge, n_pix))
    w = rng.random((n_edge, n_pix)) * (rng.random((n_edge, n_pix)) > 0.2)
    got = edge_squares(point, kernel, below, fraction, y, w)
    assert np.allclose(got, _edge_squares_numpy(point, kernel, below, fraction, y, w), rtol=1e-12, atol=1e-15)


def test_settings_are_checked():
    with pytest.raises(ValueError, match="step_px"):
        DefocusSettings(step_px=0.0)
    with pytest.raises(ValueError, match="min_edges"):
        DefocusSettings(min_edges=0)
    with pytest.raises(ValueError, match="max_shift_px"):
        DefocusSettings(max_shift_px=True)


# ------------------------------------------------------------------ the camera key
def test_camera_key_round_trip_and_checks():
    d = {"width": 400, "focal_px": 2500.0, "principal_px": 200.0, "line_rate_hz": 2e4, "defocus_px": 2.5}
    cam = camera_from_dict(d)
    assert cam.defocus_px == 2.5 and camera_from_dict(cam.to_dict()) == cam
    assert "defocus_px" not in CAM.to_dict()
    for bad in (-1.0, 1e3, "2"):
        with pytest.raises(CameraFileError, match="defocus_px"):
            camera_from_dict({**d, "defocus_px": bad})


# ------------------------------------------------------------------ across the sensor: the averaged silhouette
def test_blur_across_the_sensor_is_the_mean_over_moved_viewing_planes():
    # without motion along y and z a viewing plane moved by c pixels (c z / f metres) is the
    # same plane at the line time moved by c z / (f vx): the blurred model is the mean of the
    # sharp one at those times, weighted by the blur's marginal (edges weighted by presence)
    m = BallMotion(0.03, 0.004, (0.0, 0.05, 2.5), (20.0, 0.0, 0.0))
    blurred = replace(CAM, defocus_px=3.0)
    t = np.arange(40, 120) / CAM.line_rate_hz
    me = averaged_model(blurred, m.to_params()[None], m.radius_m, t, n_nodes=8)
    c, w = blur_offsets(blurred)
    dt = c * m.position_m[2] / (CAM.focal_px * m.velocity_mps[0])
    parts = [averaged_model(CAM, m.to_params()[None], m.radius_m, t + d, n_nodes=8) for d in dt]
    pres = sum(wk * p.presence[0] for wk, p in zip(w, parts))
    area = sum(wk * p.area_px[0] for wk, p in zip(w, parts))
    left = sum(wk * p.presence[0] * p.left_px[0] for wk, p in zip(w, parts)) / np.where(pres > 0, pres, 1)
    seen = pres > 1e-3
    assert np.allclose(me.presence[0], pres, atol=1e-9)
    assert np.allclose(me.area_px[0], area, atol=1e-6)
    assert np.allclose(me.left_px[0][seen], left[seen], atol=1e-6)
    # and it reaches further than the sharp model: the ball's ends spread over more lines
    sharp = averaged_model(CAM, m.to_params()[None], m.radius_m, t, n_nodes=8)
    assert (me.presence[0] > 0).sum() > (sharp.presence[0] > 0).sum()


# ------------------------------------------------------------------ along the sensor: measured on a render
def _blurred_render(diameter_px: float, m: BallMotion, seed: int, oversample: int = 8) -> np.ndarray:
    """A noisy 12-bit image of a uniform ball, blurred along the sensor by a blur circle's marginal.

    Rendered on a sensor ``oversample`` times finer (its pixels' centres at
    the coarse pixels' sub-positions), blurred there and binned: the blur's
    convolution and the pixel's width commute.
    """
    k = oversample
    fine = replace(CAM, width=CAM.width * k, focal_px=CAM.focal_px * k, principal_px=CAM.principal_px * k + (k - 1) / 2)
    clean = render(fine, (m, Appearance.flat(0.8)), 160, background_level=0.1, noise=None).clean
    if diameter_px > 0:
        ker = blur_kernel(diameter_px * k, 1.0)
        clean = np.stack([np.convolve(row, ker, mode="same") for row in clean])
    coarse = clean.reshape(clean.shape[0], CAM.width, k).mean(axis=2)
    rng = np.random.default_rng(seed)
    return np.clip(np.rint((coarse + rng.normal(0, 0.004, coarse.shape)) * 4095), 0, 4095).astype(np.uint16)


@pytest.mark.slow
@pytest.mark.parametrize("diameter", [1.25, 1.5, 1.75, 3.0, 4.0])
def test_blur_measured_on_a_renders_edges(diameter):
    # measured 1.33, 1.55, 1.76, 3.06, 4.04 px (between the diameters tried, every 0.5 px)
    m = BallMotion(0.03, 0.004, (0.0, 0.02, 2.5), (20.0, 0.0, 0.0))
    img = _blurred_render(diameter, m, seed=1)
    (ball,) = estimate_image(img, CAM, m.radius_m, bits=12).balls
    d = ball.extra
    assert d["defocus_source"] == "image" and d["defocus_px"] == pytest.approx(diameter, abs=0.1)
    assert d["defocus_used"] and "defocus" in ball.flags


@pytest.mark.slow
def test_blur_measured_on_a_ball_whose_edge_windows_reach_the_sensors_end():
    # the right limb 2.5 px from the sensor's last pixel: its edge windows reach the end, the
    # ball is not cut (its mask does not touch the end), so its blur is measured as any other
    m = BallMotion(0.03, 0.004, (0.0, 0.167, 2.5), (20.0, 0.0, 0.0))
    limb_px = CAM.principal_px + CAM.focal_px * (m.position_m[1] + m.radius_m) / m.position_m[2]
    assert 2.0 < (CAM.width - 0.5) - limb_px < 3.0
    (ball,) = estimate_image(_blurred_render(2.0, m, seed=1), CAM, m.radius_m, bits=12).balls
    d = ball.extra
    assert "cut_sensor_end" not in ball.flags
    assert d["defocus_source"] == "image" and d["defocus_px"] == pytest.approx(2.0, abs=0.1) and d["defocus_used"]
    # a pixel further, its region reaches the end: cut, its cut side's edges are the sensor's, no blur is read
    m = replace(m, position_m=(0.0, 0.168, 2.5))
    (ball,) = estimate_image(_blurred_render(2.0, m, seed=1), CAM, m.radius_m, bits=12).balls
    assert "cut_sensor_end" in ball.flags and ball.extra["defocus_px"] is None and "defocus" not in ball.flags


@pytest.mark.slow
def test_no_blur_taken_on_a_sharp_render():
    # in focus the estimate reads 0.48 px (below the 1 px the recipe takes): neither used nor flagged
    m = BallMotion(0.03, 0.004, (0.0, 0.02, 2.5), (20.0, 0.0, 0.0))
    (ball,) = estimate_image(_blurred_render(0.0, m, seed=1), CAM, m.radius_m, bits=12).balls
    d = ball.extra
    assert d["defocus_px"] < 0.6 and not d["defocus_used"] and "defocus" not in ball.flags


def test_limb_profile_blur_along_the_sensor_is_the_convolution_of_its_coverage():
    # the blurred profile's pixel coverage against the coverage of its chords (blurred across
    # the sensor only) at finely spaced shifts, weighted by the blur circle's marginal (a
    # brute-force convolution): 12 nodes hold it within 2e-3
    from ballscan.measure.shading import LimbProfile, ShadingModel
    from ballscan.model.pixels import pixel_coverage

    m = BallMotion(0.03, 0.004, (0.0, 0.02, 2.5), (20.0, 0.0, 0.0))
    t = np.arange(200) / CAM.line_rate_hz
    me = averaged_model(CAM, m.to_params()[None], m.radius_m, t)
    law = ShadingModel(1.0, (0.0, 0.0, 0.0), 0.0, 0)
    blurred = LimbProfile(law, replace(CAM, defocus_px=2.5), m, t, np.zeros((200, CAM.width)), 1, 1.0, me.spread_px[0], me.left_px[0], me.right_px[0])
    lines = np.array([70, 80, 90])
    off = np.tile(np.arange(-4.0, 5.0), (3, 1))
    got = blurred.pixel_coverage(lines, np.ones(3), off)
    k = blur_kernel(2.5, 0.01)
    x = (np.arange(k.size) - (k.size - 1) / 2) * 0.01
    lo, hi, wgt = blurred._chords(lines, np.ones(3), 4, blurred=False)
    want = sum(wk * pixel_coverage(lo[None], hi[None], wgt[None], off + xk)[0] for wk, xk in zip(k, x))
    assert np.allclose(got, want, atol=2e-3)
    assert not np.allclose(got, pixel_coverage(lo[None], hi[None], wgt[None], off)[0], atol=2e-2)



def test_limb_profile_values_are_the_sharp_profile_averaged_along_the_sensor():
    # a shaded ball's point values with a blur against the in-focus profile at finely spaced
    # shifts weighted by the blur circle's marginal (a point's value steps at the edge: 12
    # nodes hold the convolution within 0.012, whole pixels' coverage within 2e-3 above); the
    # surface's brightness stays unblurred
    from ballscan.measure.shading import LimbProfile, ShadingModel

    m = BallMotion(0.03, 0.004, (0.0, 0.02, 2.5), (20.0, 0.0, 0.0))
    t = np.arange(200) / CAM.line_rate_hz
    me = averaged_model(CAM, m.to_params()[None], m.radius_m, t)
    law = ShadingModel(0.3, (0.2, -0.3, -0.6), 0.0, 0)
    blurred = LimbProfile(law, replace(CAM, defocus_px=2.0), m, t, np.zeros((200, CAM.width)), 1, 1.0, me.spread_px[0], me.left_px[0], me.right_px[0])
    lines, sides = np.array([75, 80, 85]), np.array([1.0, -1.0, 1.0])
    off = np.tile(np.linspace(-2.0, 3.0, 11), (3, 1))
    got, _ = blurred(lines, sides, off)
    k = blur_kernel(2.0, 0.005)
    x = (np.arange(k.size) - (k.size - 1) / 2) * 0.005
    sharp = blurred.sharp()
    want = sum(wk * np.nan_to_num(sharp(lines, sides, off + xk)[0]) for wk, xk in zip(k, x))
    assert np.allclose(got, want, atol=0.015) and not np.allclose(got, sharp(lines, sides, off)[0], atol=0.05)
    inside = np.full((3, 1), 1.0)
    assert np.allclose(blurred.surface(lines, sides, inside), sharp.surface(lines, sides, inside))
