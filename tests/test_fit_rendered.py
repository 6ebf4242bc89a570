"""The "fit" method end to end on rendered images: accuracy, robustness, honest sigmas.

Targets and what is met (see the module's tests for the tolerances used):

* flat, noise-free tennis ball at 3 m (f = 3000 px, 50 kHz): perpendicular
  crossing, speed error target < 0.01 %, achieved 0.0003 %; 30 degrees
  oblique along the sensor, target < 0.05 %, achieved 0.0024 %; in depth
  0.054 % with the renderer's default sampling (16 x 4 x 8 samples per edge
  pixel, 16 x 16 x 16 on the ball's first and last lines; V.z reads the
  other lines' 0.004 px RMS of sampling error) and 0.0082 % (met) with
  16 x 16 x 64 everywhere; position target < 0.5 mm, achieved < 0.03 mm.
* clean reference scenes (POV-Ray, textured and shaded): median speed error
  target <= 0.3 %, achieved 0.11 % (worst 0.72 %), with the shading-aware
  second pass.
* 1-sigma coverage of the speed over noisy renders of an untextured ball
  crossing at 30 degrees: 60-76 % (measured 73.0 %; the sensor has 0.8 %
  PRNU, so the matched edges, which are for flat-fielded sensors, are not
  used: with them 69.5 %).
* the default on a flat-fielded sensor (no PRNU, Gaussian noise): matched
  edges and the pixels of the ends and spread lines, speed RMSE 1.05x the
  pixel bound over 40 oblique renders (bench_fit, 100: 1.03x / 1.06x).
* the fit of the ends' pixels (``pixels=True``) on a flat ball rendered with
  a finely sampled exposure: noise-free perpendicular 0.0003 %; with
  Gaussian pixel noise its speed RMSE near the pixel Cramér–Rao bound.
"""

from __future__ import annotations

import json
import math
from dataclasses import replace

import numpy as np
import pytest

from ballscan.geometry.camera import LineScanCamera, load_camera
from ballscan.pipeline.estimate import estimate_image
from ballscan.pipeline.recipe import Recipe
from ballscan.measure.images import LineImage, load_image
from ballscan.geometry.motion import BallMotion
from ballscan.model.render import Appearance, RenderSettings, SensorNoise, apply_sensor, render

from .conftest import DATA

SCENES = DATA / "scenes"
CAM = LineScanCamera(2048, 3000.0, 1023.5, 50000.0, None)
R_TENNIS = 0.0335
# the continuous exposure, as the fit's model has it (the default 4 x 8
# height x time samples leave 0.004 px RMS on a line's area, and 16 x 16 on
# the first and last lines up to 0.01 px)
FINE = RenderSettings(samples_across=16, samples_time=64, cap_across=16, cap_time=64)


def _image(data: np.ndarray) -> LineImage:
    bits = 8 if data.dtype == np.uint8 else 16
    return LineImage(data.astype(float), float(np.iinfo(data.dtype).max), bits, "render")


def _estimate(data: np.ndarray, camera: LineScanCamera, radius: float):
    balls = estimate_image(_image(data), camera, radius).balls
    if len(balls) != 1:
        raise AssertionError(f"expected one ball, found {len(balls)}")
    return balls[0]


#: the default recipe without the limb term in its fits' covariance (FitSettings.limb_residual_gain)
_NO_LIMB_TERM = Recipe(**{name: replace(getattr(Recipe(), name), limb_residual_gain=0.0) for name in ("loose_fit", "pixel_fit", "spread_fit", "edge_fit")})


def _oblique(deg: float, speed: float = 30.0, towards: str = "z") -> BallMotion:
    a = math.radians(deg)
    side = speed * math.sin(a)
    v = (speed * math.cos(a), side, 0.0) if towards == "y" else (speed * math.cos(a), 0.0, side)
    return BallMotion(R_TENNIS, 0.002, (0.0, 0.01, 3.0), v)


@pytest.mark.parametrize(
    ("deg", "towards", "max_speed_pct", "fine"),
    # the targets are 0.01 % (perpendicular) and 0.05 % (30 degrees):
    # measured 0.0003 % and 0.0024 % (along the sensor); in depth 0.054 % with
    # the renderer's default 4 x 8 (height x time) samples per edge pixel
    # (16 x 16 on the cap lines; V.z, the weak axis, reads the other lines'
    # 0.004 px RMS of sampling error), and 0.0082 % with 16 x 64.  Coarse
    # caps (up to 0.066 px off) give 0.0040 % / 0.0063 % / 0.081 % and hide
    # a -0.011 % bias of the spread edges next to the ends (see EdgeSettings.limb_texture_tol and
    # LimbProfile.pixel_coverage); with the caps fixed but before the exact
    # coverage 0.0042 % / 0.0081 % / 0.074 % / 0.030 %
    [(0.0, "z", 0.01, False), (30.0, "y", 0.05, False), (30.0, "z", 0.15, False), (30.0, "z", 0.05, True)],
)
def test_flat_noise_free_render_accuracy(deg, towards, max_speed_pct, fine):
    m = _oblique(deg, towards=towards)
    settings = dict(settings=FINE) if fine else {}
    r = render(CAM, (m, Appearance.flat()), 200, background_level=0.1, noise=None, **settings)
    b = _estimate(r.image, CAM, R_TENNIS)
    speed_err = abs(b.speed_mps - m.speed_mps) / m.speed_mps * 100
    pos_err_mm = 1000 * np.linalg.norm(np.asarray(b.position_m) - m.position_m)
    assert speed_err < max_speed_pct
    assert pos_err_mm < 0.5
    assert abs(b.t_c_s - m.t_c_s) * CAM.line_rate_hz < 0.01  # lines
    assert b.velocity_sigma_mps[2] < 1.0 and "degenerate" not in b.flags


@pytest.mark.parametrize("seed", [0, 1, 2, 3])
def test_noisy_textured_tennis_ball_is_never_wildly_wrong(seed):
    # a seam crossing the limb made vz = +131 m/s before outlier handling
    m = BallMotion(R_TENNIS, 0.002, (0.0, 0.01, 3.0), (30.0, 2.0, 0.0))
    app = Appearance(texture="tennis", orientation_seed=seed, spin_rps=30.0)
    r = render(CAM, (m, app), 200, background_level=0.1, noise=SensorNoise(), seed=seed)
    b = _estimate(r.image, CAM, R_TENNIS)
    dv = np.asarray(b.velocity_mps) - m.velocity_mps
    sv = np.asarray(b.velocity_sigma_mps)
    # vx, vy within 3 sigma; vz within 3.5: seed 1's seam next to the limb
    # puts vz +16.5 m/s off, 3.25 sigma with the end lines' levelled areas
    # (sigma 5.1 m/s: the areas add information, the seam's bias of the
    # edges stays; 2.8 sigma of 5.8-6 m/s without them).  vx within 3.5 too:
    # with the partial lines levelled seed 1's vx is 3.3 sigma
    # off (-0.049 +- 0.015 m/s); over 142 of our own textured renders V.x
    # lies within 3 sigma on 95.1 % (94.4 % with the partial lines loose)
    assert np.all(np.abs(dv) < np.array([3.5, 3.0, 3.5]) * sv)
    assert abs(b.speed_mps - m.speed_mps) < 3 * b.speed_sigma_mps
    # vz is the weak axis (sigma 4-8 m/s here): within 3 sigma it can move
    # the speed by ~15 %.  Measured: seed 1 +12.9 % (vz +17 +- 6 m/s)
    # with the shading-aware second pass, -0.3 % without it; seeds 0,
    # 2, 3 within 1.3 %.  A seam next to the limb biases the edges whichever
    # level model is used.
    assert abs(b.speed_mps - m.speed_mps) / m.speed_mps < 0.15
    # z0 errors 0.5, 6.5, 2.6, 3.0 mm (sigma 1.1-1.8 mm: seed 1 is 3.9 sigma,
    # the seam biasing the width on many lines; 1.9-2.7 mm without the second
    # pass)
    assert 1000 * np.linalg.norm(np.asarray(b.position_m) - m.position_m) < 8.0
    assert sv[2] < 15.0  # vz is weak but bounded; vx, vy are sharp
    # the measurements fix vx and vy to 0.05 m/s; the reported sigmas also
    # hold the seam's limb error that the motion absorbs
    # (FitSettings.limb_residual_gain): its trend in vy, up to 0.12 m/s on
    # seeds 0-3, its curvature in vx, up to 0.06 m/s (seed 3; without it
    # vx's sigma covered the error on 37-46 % of 170 seamed tennis balls of
    # benchmarks/bench_coverage.py, with it 64-71 %)
    sv_measured = np.asarray(estimate_image(_image(r.image), CAM, R_TENNIS, recipe=_NO_LIMB_TERM).balls[0].velocity_sigma_mps)
    assert sv_measured[0] < 0.05 and sv_measured[1] < 0.05
    assert sv[0] < 0.1 and sv[1] < 0.15


def _scene_balls(name: str):
    truth = json.loads((SCENES / f"{name}.truth.json").read_text())
    return truth.get("balls", [truth])


SCENE_NAMES = ["pub_tennis_serve", "pub_pingpong", "pub_tennis_bright_bg", "pub_lab_rail_6deg", "pub_cut_first_line", "pub_two_close"]


def test_clean_reference_scenes_speed_error():
    errs, zs = [], []
    for name in SCENE_NAMES:
        cam = load_camera(SCENES / f"{name}.camera.toml")
        img = load_image(SCENES / "clean" / f"{name}.png")
        truth = _scene_balls(name)
        est = estimate_image(img, cam, truth[0]["radius_m"]).balls
        assert len(est) == len(truth), name
        for tb in truth:
            eb = min(est, key=lambda e: abs(e.t_c_s - tb["t_c_s"]))
            s_true = float(np.linalg.norm(tb["velocity_mps"]))
            errs.append(abs(eb.speed_mps - s_true) / s_true * 100)
            zs.append(abs(eb.speed_mps - s_true) / eb.speed_sigma_mps)
            pos_err = np.linalg.norm(np.asarray(eb.position_m) - tb["position_m"])
            assert pos_err < 0.005, name  # metres
    # measured median 0.11 %, worst 0.72 % (the serve: V.z sigma 10 m/s; without the shading-aware pass 0.22 % and 0.80 %)
    assert float(np.median(errs)) < 0.3
    assert max(errs) < 1.0
    # the clean 16-bit images have almost no pixel noise: the sigmas come from
    # the systematic floor and the residual scatter, and still cover the error
    assert np.mean(np.asarray(zs) < 3) >= 6 / 7


@pytest.mark.slow
def test_speed_sigma_is_honest_over_noisy_renders():
    m = _oblique(30.0)
    clean = render(CAM, (m, Appearance.flat()), 200, background_level=0.1, noise=None).clean
    noise = SensorNoise()
    inside = []
    for seed in range(200):
        data, _ = apply_sensor(clean, noise, seed)
        b = _estimate(data, CAM, R_TENNIS)
        inside.append(abs(b.speed_mps - m.speed_mps) <= b.speed_sigma_mps)
    frac = float(np.mean(inside))
    assert 0.60 <= frac <= 0.76, frac


def _noisy_flat_runs(m: BallMotion, seed: int, pixels: bool = False, runs: int = 40):
    """Speed errors, reported sigmas and estimates over ``runs`` noisy copies (5 DN on 700) of a finely rendered flat ball."""
    from ballscan.measure.detection import detect
    from ballscan.pipeline.estimate import estimate_region

    clean = render(CAM, (m, Appearance.flat(0.8)), 200, background_level=0.1, noise=None, settings=FINE).clean
    t = np.arange(200) / CAM.line_rate_hz
    rng = np.random.default_rng(seed)
    out = []
    for _ in range(runs):
        img = LineImage(clean * 1000.0 + 5.0 * rng.standard_normal(clean.shape), 1e12, 16, "fine")
        det = detect(img)
        out.append(estimate_region(img, det, det.regions[0], CAM, R_TENNIS, t, Recipe(pixels=pixels)))
    return np.array([b.speed_mps - m.speed_mps for b in out]), np.array([b.speed_sigma_mps for b in out]), out


@pytest.mark.slow
def test_pixel_fit_of_the_ends_near_the_cramer_rao_bound():
    """pixels=True: exact on a noise-free render, near the pixel bound with noise, sigma not too small."""
    from ballscan.solve.precision import pixel_crlb

    m0 = _oblique(0.0)
    clean = render(CAM, (m0, Appearance.flat(0.8)), 200, background_level=0.1, noise=None, settings=FINE).clean
    b = estimate_image(LineImage(clean * 65535.0, 65535.0, 16, "fine"), CAM, R_TENNIS, recipe=Recipe(pixels=True)).balls[0]
    assert b.extra["pixels"] == "used"
    # measured -0.0003 % (edges and areas: -0.012 % on this render), V.z 2e-5 m/s
    assert abs(b.speed_mps - m0.speed_mps) / m0.speed_mps < 2e-5
    assert abs(b.velocity_mps[2]) < 0.01

    m = _oblique(30.0)
    bound = pixel_crlb(CAM, m, 5.0, 700.0)
    err, sig, runs = _noisy_flat_runs(m, seed=7, pixels=True)
    used = [b.extra["pixels"] == "used" for b in runs]
    rmse = float(np.sqrt(np.mean(err**2)))
    # measured over 100 runs of benchmarks/bench_fit.py at this geometry:
    # 1.10x the bound (edges and levelled areas: 1.94x); 40 runs scatter by
    # about 20 %
    # one image of 40 looked shaded (a poor key-point guess: light 4 % of
    # the contrast, level scatter 2.6 %) and kept the edge fit
    assert sum(used) >= 36
    assert rmse < 1.6 * bound.speed_sigma_mps
    assert 0.5 <= np.mean(np.abs(err) <= sig) <= 0.97


@pytest.mark.slow
def test_default_fit_near_the_cramer_rao_bound_on_a_flat_fielded_sensor():
    """The default on a uniform ball and a sensor without PRNU: matched edges and the spread lines' pixels."""
    from ballscan.solve.precision import pixel_crlb

    m = _oblique(30.0)
    bound = pixel_crlb(CAM, m, 5.0, 700.0)
    err, sig, runs = _noisy_flat_runs(m, seed=11)
    used = [b.extra["pixels"] == "spread" and b.extra["edges"] == "matched" for b in runs]
    rmse = float(np.sqrt(np.mean(err**2)))
    # measured over 100 runs of benchmarks/bench_fit.py at this geometry:
    # 1.06x the bound (the window edges and levelled areas: 1.25x); these
    # 40 runs: 1.05x, 1-sigma coverage 0.72 (40 runs scatter by about 20 %)
    assert sum(used) >= 36
    # seeded: 1.05x measured; the matched-edge fit alone on these images 1.25x
    assert rmse < 1.2 * bound.speed_sigma_mps
    assert 0.4 <= np.mean(np.abs(err) <= sig) <= 0.95


def test_pixel_fit_refuses_a_shaded_ball():
    """A ball lit from the side is not uniform: the pixel fit is not used and says why."""
    app = Appearance(ball_level=0.8, shading=True, light_dir=(-0.35, -0.45, -0.82), ambient=0.35)
    m = _oblique(0.0)
    clean = render(CAM, (m, app), 200, background_level=0.1, noise=None).clean
    img = LineImage(clean * 65535.0, 65535.0, 16, "shaded")
    asked = estimate_image(img, CAM, R_TENNIS, recipe=Recipe(pixels=True)).balls[0]
    plain = estimate_image(img, CAM, R_TENNIS).balls[0]
    assert asked.extra["pixels"] == "not_uniform" and plain.extra["pixels"] == "off"
    assert asked.velocity_mps == plain.velocity_mps


def test_pixel_fit_cut_ball_lateral_motion_and_no_shading():
    """The pixel fit measures a ball cut by the sensor's start; refuses a ball moving along the sensor;
    with the shading pass off and the pixel fit refused the result is the first pass's."""
    cut = BallMotion(R_TENNIS, 0.003, (0.0, -0.998, 3.0), (30.0, 0.0, 0.0))  # centre at u = 25 px
    clean = render(CAM, (cut, Appearance.flat(0.8)), 300, background_level=0.1, noise=None).clean
    img = LineImage(clean * 1000.0 + 5.0 * np.random.default_rng(0).standard_normal(clean.shape), 1e12, 16, "cut")
    b = estimate_image(img, CAM, R_TENNIS, recipe=Recipe(pixels=True)).balls[0]
    # measured: used, -0.0009 +- 0.0021 m/s (edges and areas: -0.0028 +- 0.020)
    assert b.extra["pixels"] == "used" and "cut_sensor_end" in b.flags
    assert abs(b.speed_mps - cut.speed_mps) < 3 * b.speed_sigma_mps

    lateral = BallMotion(R_TENNIS, 0.002, (0.0, 0.01, 3.0), (21.2, 21.2, 0.0))  # 0.42 px along the sensor per exposure
    clean = render(CAM, (lateral, Appearance.flat(0.8)), 200, background_level=0.1, noise=None).clean
    assert estimate_image(LineImage(clean * 65535.0, 65535.0, 16, "lateral"), CAM, R_TENNIS, recipe=Recipe(pixels=True)).balls[0].extra["pixels"] == "lateral_motion"

    app = Appearance(ball_level=0.8, shading=True, light_dir=(-0.35, -0.45, -0.82), ambient=0.35)
    clean = render(CAM, (_oblique(0.0), app), 200, background_level=0.1, noise=None).clean
    img = LineImage(clean * 65535.0, 65535.0, 16, "shaded")
    asked = estimate_image(img, CAM, R_TENNIS, recipe=Recipe(shading=False, pixels=True)).balls[0]
    plain = estimate_image(img, CAM, R_TENNIS, recipe=Recipe(shading=False)).balls[0]
    assert asked.extra["pixels"] == "not_uniform" and asked.extra["shading_pass"] == "off"
    assert asked.velocity_mps == plain.velocity_mps and asked.extra["shading"] is None
