"""Key points and the closed-form initial guess, Eq. (3)-(7)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from ballscan.geometry.camera import LineScanCamera
from ballscan.solve.initial import (
    KeyPoints,
    ellipse_starts,
    find_keypoints,
    fit_silhouette_ellipse,
    half_contrast_edges,
    initial_guess,
)
from ballscan.geometry.motion import BallMotion
from ballscan.model.silhouette import silhouette


def exact_keypoints(cam: LineScanCamera, m: BallMotion, u_sigma: float = 0.05) -> KeyPoints:
    """Key points of the ideal chord model: A and B are the sphere's front and back points."""
    R, vx = m.radius_m, m.velocity_mps[0]
    t_a, t_b = m.t_c_s - R / vx, m.t_c_s + R / vx
    ca, cb = m.centre(np.array([t_a, t_b]))
    u_a, u_b = cam.project(np.array([ca[1], cb[1]]), np.array([ca[2], cb[2]]))
    sil = silhouette(cam, m, np.array([m.t_c_s]), model="chord")
    return KeyPoints(
        line_a=t_a * cam.line_rate_hz, line_b=t_b * cam.line_rate_hz, u_a=float(u_a), u_b=float(u_b),
        u_a_sigma_px=u_sigma, u_b_sigma_px=u_sigma, line_o=m.t_c_s * cam.line_rate_hz,
        u_c=float(sil.right_px[0]), u_d=float(sil.left_px[0]), t_a_s=t_a, t_b_s=t_b,
    )


@pytest.mark.parametrize(
    "pos,vel",
    [((0, 0.02, 3.0), (30.0, 0.0, 0.0)), ((0, -0.3, 2.5), (20.0, 6.0, 0.0)), ((0, 0.4, 4.0), (25.0, -8.0, 4.0))],
)
def test_exact_keypoints_give_exact_motion(pos, vel):
    cam = LineScanCamera(4096, 4000.0, 2047.5, 50000.0)
    m = BallMotion(0.0335, 0.002, pos, vel)
    ig = initial_guess(exact_keypoints(cam, m, u_sigma=1e-4), cam, m.radius_m, tip_sigma_px=1e-4)
    np.testing.assert_allclose(ig.motion.position_m, m.position_m, atol=1e-9)
    assert ig.motion.t_c_s == pytest.approx(m.t_c_s, abs=1e-12)
    if vel[1] == 0 and vel[2] == 0:
        assert ig.degenerate  # u_a == u_b: Eq. (5)-(6) singular
        np.testing.assert_allclose(ig.motion.velocity_mps, vel, atol=1e-9)
    else:
        assert not ig.degenerate
        np.testing.assert_allclose(ig.motion.velocity_mps, vel, rtol=1e-7, atol=1e-6)


def test_paper_sign_convention_phi_positive():
    cam = LineScanCamera(2048, 3000.0, 1023.5, 50000.0)
    m = BallMotion(0.0335, 0.002, (0, 0.1, 3.0), (30.0, 0.0, 0.0))
    kp = exact_keypoints(cam, m)
    assert kp.u_c > kp.u_d
    ig = initial_guess(kp, cam, m.radius_m)
    assert ig.phi_rad > 0
    # gamma = arctan(y'_c / f) with y' = -f n: the tip c lies at positive y here, so gamma < 0
    assert ig.gamma_rad == pytest.approx(math.atan(-cam.backproject(np.array([kp.u_c]))[0]))


def test_ill_conditioned_depth_motion_is_flagged_not_divided():
    cam = LineScanCamera(2048, 3000.0, 1023.5, 50000.0)
    m = BallMotion(0.0335, 0.002, (0, 0.02, 3.0), (30.0, 1.0, 0.0))  # u_a, u_b only ~2 px apart
    kp = exact_keypoints(cam, m)
    # a 0.3 px error on one tip would make Eq. (5)-(6) invent metres per second of V.z
    from dataclasses import replace

    ig = initial_guess(replace(kp, u_c=kp.u_c + 0.3), cam, m.radius_m)
    assert ig.depth_fallback and not ig.degenerate
    assert ig.depth_motion_sigma_m > 2 * m.radius_m
    assert ig.motion.velocity_mps[2] == 0.0
    assert ig.motion.velocity_mps[1] == pytest.approx(1.0, abs=0.2)  # V.y still from a and b


def test_duration_counts_first_to_last_line():
    cam = LineScanCamera(2048, 3000.0, 1023.5, 1000.0)
    kp = KeyPoints(10.0, 30.0, 1000.0, 1000.0, 0.05, 0.05, 20.0, 1040.0, 960.0, 0.010, 0.030)
    ig = initial_guess(kp, cam, 0.05)
    assert ig.duration_s == pytest.approx(0.020)
    assert ig.motion.velocity_mps[0] == pytest.approx(2 * 0.05 / 0.020)
    assert ig.motion.t_c_s == pytest.approx(0.020)


def test_crossing_direction_sets_vx_sign():
    cam = LineScanCamera(2048, 3000.0, 1023.5, 1000.0, crossing="-x")
    kp = KeyPoints(10.0, 30.0, 1000.0, 1000.0, 0.05, 0.05, 20.0, 1040.0, 960.0, 0.010, 0.030)
    assert initial_guess(kp, cam, 0.05).motion.velocity_mps[0] < 0


def test_half_contrast_edges_linear_interpolation():
    p = np.array([0.0, 0.0, 0.25, 0.75, 1.0, 1.0, 0.6, 0.2, 0.0])
    left, right = half_contrast_edges(p, inner_px=3)
    assert left == pytest.approx(2.5)  # local level 1.0
    assert right == pytest.approx(6.25)  # local level 1.0: 0.5 between 0.6 (px 6) and 0.2 (px 7)
    assert all(math.isnan(v) for v in half_contrast_edges(np.zeros(5)))


def test_half_contrast_edges_follow_a_shaded_limb():
    # bright left side, a limb at 30 % of the contrast on the right: the right
    # edge must sit at half of 0.3, not at half of the global contrast
    p = np.array([0.0, 0.0, 0.5, 1.0, 0.9, 0.7, 0.5, 0.35, 0.3, 0.3, 0.15, 0.0, 0.0])
    left, right = half_contrast_edges(p)
    assert left == pytest.approx(2.0)
    assert right == pytest.approx(10 - 0.025 / 0.15)  # 0.15 between 0.3 (px 9) and 0.15 (px 10)


def test_keypoints_the_same_with_a_row_or_a_box_of_sigmas():
    box = np.zeros((9, 12))
    box[2:7, 3:9] = 1.0
    box[4, 2] = 0.4
    sig = np.linspace(0.01, 0.05, 12)
    a = find_keypoints(box, sig, box > 0.3, 10, 20, np.arange(40) * 1e-5)
    b = find_keypoints(box, np.tile(sig, (9, 1)), box > 0.3, 10, 20, np.arange(40) * 1e-5)
    c = find_keypoints(box, sig[None, :], box > 0.3, 10, 20, np.arange(40) * 1e-5)
    assert a == b == c


@pytest.mark.parametrize("end", ["first", "last"])
def test_keypoint_on_an_end_line_darker_than_the_background(end):
    """A bright ball whose first (last) line shows only its shaded end, below the background: u_a (u_b) is that line's centroid, not NaN."""
    box = np.zeros((9, 12))
    box[2:7, 3:9] = 1.0
    r = 2 if end == "first" else 6
    box[r, :] = 0.0
    box[r, 5:8] = [-0.2, -0.4, -0.2]  # centroid at pixel 6
    mask = np.abs(box) > 0.1
    kp = find_keypoints(box, np.full(12, 0.01), mask, 10, 20, np.arange(40) * 1e-5)
    u = kp.u_a if end == "first" else kp.u_b
    assert u == pytest.approx(26.0, abs=1e-9)
    assert math.isfinite(kp.u_a_sigma_px) and math.isfinite(kp.u_b_sigma_px)
    cam = LineScanCamera(width=60, focal_px=2000.0, principal_px=30.0, line_rate_hz=1e5)
    g = initial_guess(kp, cam, 0.02)
    assert np.all(np.isfinite(g.motion.velocity_mps))


# ------------------------------------------------------- cut balls' ellipse
def _ellipse_points(t0=100.0, h=60.0, u0=20.0, a=0.08, r=30.0, noise=0.05, seed=3):
    """Both limbs of a sheared ellipse on lines t0 - h .. t0 + h, with Gaussian noise (pixels)."""
    rng = np.random.default_rng(seed)
    t = np.arange(math.ceil(t0 - h) + 1, math.floor(t0 + h))
    q = np.sqrt(1.0 - ((t - t0) / h) ** 2)
    lines = np.concatenate([t, t]).astype(float)
    side = np.concatenate([-np.ones(t.size), np.ones(t.size)])
    u = u0 + a * (lines - t0) + side * r * np.concatenate([q, q]) + noise * rng.standard_normal(lines.size)
    return lines, u, side


@pytest.mark.parametrize("keep", ["right_of_zero", "left_of_40"])
def test_ellipse_from_one_limb_beyond_a_sensor_end(keep):
    """A ball cut by the sensor's end: one limb seen (and the other where it is on the sensor); the ellipse comes back."""
    lines, u, side = _ellipse_points()
    ok = u > 1.5 if keep == "right_of_zero" else u < 38.5
    seen = lines[ok]
    e = fit_silhouette_ellipse(lines[ok], u[ok], side[ok], ellipse_starts(seen.min(), seen.max()))
    assert e.line_o == pytest.approx(100.0, abs=0.3)
    assert e.half_lines == pytest.approx(60.0, abs=0.5)
    assert e.u_centre_px == pytest.approx(20.0, abs=0.3)
    assert e.radius_px == pytest.approx(30.0, abs=0.3)
    assert e.slope_px_per_line == pytest.approx(0.08, abs=0.005)
    assert e.rms_px < 0.08


@pytest.mark.parametrize("cut_first", [True, False])
def test_ellipse_of_a_ball_cut_by_an_image_end(cut_first):
    """40 % of the ball's lines seen, from its seen end: t0 beyond the image, found from the limbs' curvature."""
    lines, u, side = _ellipse_points(noise=0.02)
    ok = lines >= 100.0 - 60.0 + 0.6 * 120.0 if cut_first else lines <= 40.0 + 0.4 * 120.0
    seen = lines[ok]
    e = fit_silhouette_ellipse(lines[ok], u[ok], side[ok], ellipse_starts(seen.min(), seen.max(), cut_first, not cut_first))
    assert e.line_o == pytest.approx(100.0, abs=1.5)
    assert e.half_lines == pytest.approx(60.0, abs=1.5)
    assert e.radius_px == pytest.approx(30.0, abs=0.3)


def test_ellipse_of_a_ball_cut_by_both_image_ends():
    """The middle 70 % of the ball's lines seen: its ends placed by the limbs' curvature alone."""
    lines, u, side = _ellipse_points(noise=0.02)
    ok = np.abs(lines - 100.0) <= 0.7 * 60.0
    seen = lines[ok]
    e = fit_silhouette_ellipse(lines[ok], u[ok], side[ok], ellipse_starts(seen.min(), seen.max(), True, True))
    assert e.line_o == pytest.approx(100.0, abs=1.0)
    assert e.half_lines == pytest.approx(60.0, abs=2.0)
    assert e.radius_px == pytest.approx(30.0, abs=0.3)


def test_ellipse_fit_refuses_straight_limbs():
    """Two straight edges (a band across the sensor, not a ball): no ellipse of a ball's length fits, so no key points millions of lines away."""
    rng = np.random.default_rng(1)
    t = np.arange(0.0, 41.0)
    lines = np.concatenate([t, t])
    side = np.concatenate([-np.ones(t.size), np.ones(t.size)])
    u = np.where(side < 0, 5.0, 60.0) + 0.3 * rng.standard_normal(lines.size)
    with pytest.raises(ValueError, match="not one ball's limb"):
        fit_silhouette_ellipse(lines, u, side, ellipse_starts(0.0, 40.0))


def test_ellipse_fit_refuses_too_few_points():
    with pytest.raises(ValueError, match="at least 6"):
        fit_silhouette_ellipse(np.arange(5.0), np.zeros(5), np.ones(5), ellipse_starts(0.0, 4.0))


def test_keypoints_of_a_ball_cut_by_pixel_zero():
    """A drawn disc whose centre lies 5 px before pixel 0: the tips c, d straddle the sensor's start."""
    t0, h, u0, r = 40.0, 30.0, -5.0, 20.0
    n_lines, width = 81, 60
    rows = np.arange(n_lines)[:, None]
    cols = np.arange(width)[None, :]
    # coverage of each pixel by the ellipse, 8x supersampled along the sensor
    sub = (np.arange(8) + 0.5) / 8 - 0.5
    half = r * np.sqrt(np.clip(1.0 - ((rows - t0) / h) ** 2, 0.0, None))
    box = np.mean([(np.abs(cols + s - u0) <= half) for s in sub], axis=0)
    kp = find_keypoints(box, np.full(width, 0.01), box > 0.25, 0, 0, np.arange(n_lines) * 1e-4, sensor_width_px=width)
    assert kp.cut == "sensor"
    assert kp.line_o == pytest.approx(t0, abs=0.5)
    assert kp.u_c == pytest.approx(u0 + r, abs=0.3) and kp.u_d == pytest.approx(u0 - r, abs=0.5)
    assert kp.line_b - kp.line_a == pytest.approx(2 * h, abs=2.0)
    assert kp.t_a_s == pytest.approx(kp.line_a * 1e-4)
