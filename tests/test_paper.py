"""The paper's refinement (Eq. (7)-(10)) end to end on rendered images with known truth."""

from __future__ import annotations

import numpy as np
import pytest

from ballscan.geometry.camera import LineScanCamera, line_times
from ballscan.pipeline.estimate import estimate_image
from ballscan.pipeline.recipe import Recipe
from ballscan.measure.images import LineImage
from ballscan.geometry.motion import BallMotion
from ballscan.solve.paper import gradient_image, render_coverage
from ballscan.model.render import Appearance, SensorNoise, render


def _image(cam, motion, n_lines, app, background, seed=3, noise=SensorNoise()):
    r = render(cam, (motion, app), n_lines, background_level=background, noise=noise, seed=seed)
    full = 2.0 ** (8 if noise is not None else 16) - 1
    return LineImage(r.image.astype(float), full, 8, "rendered")


def test_render_coverage_matches_silhouette_area():
    cam = LineScanCamera(2048, 3000.0, 1023.5, 50000.0)
    m = BallMotion(0.0335, 0.0015, (0, 0.02, 3.0), (30.0, 2.0, -1.0))
    t = line_times(cam, 150)
    cov = render_coverage(cam, m, t, np.arange(950, 1120))
    from ballscan.model.silhouette import silhouette

    np.testing.assert_allclose(cov.sum(axis=1), silhouette(cam, m, t).area_px, atol=1e-9)
    g = gradient_image(cov)
    assert g.shape == (150, 169) and np.all(g >= 0)


CASES = {
    # name: camera, motion, lines, speed error (%) the refinement must stay under
    # perpendicular: the refined speed error over noise seeds 0-5, dark and
    # bright balls, is 0.001-0.31 % (V.z, the gradient energy's flat axis;
    # seed 3's dark ball, the one tested, 0.31 %; 0.11 % with coarsely
    # rendered end lines): 0.4 %
    "perpendicular": (LineScanCamera(2048, 3000.0, 1023.5, 50000.0), BallMotion(0.0335, 0.0015, (0, 0.02, 3.0), (30.0, 0, 0)), 150, 0.4),
    "oblique-30deg": (LineScanCamera(2048, 3000.0, 1023.5, 50000.0), BallMotion(0.0335, 0.0015, (0, 0.02, 3.0), (25.98, 15.0, 0)), 150, 3.0),
    "table-tennis": (LineScanCamera(1024, 2800.0, 511.5, 30000.0), BallMotion(0.02, 0.0036, (0, -0.04, 1.8), (12.37, 0.0, 0.0)), 220, 1.0),
    "large-slow": (LineScanCamera(2048, 2500.0, 1023.5, 2000.0), BallMotion(0.11, 0.025, (0, 0.05, 4.0), (6.0, 0.5, 0.0)), 100, 0.5),
}


_KEYS = [(name, dark) for name in CASES for dark in (False, True)]


@pytest.fixture(scope="module")
def paper_results():
    """The paper method on every flat case, bright and dark ball (rendered once)."""
    out = {}
    for name, dark in _KEYS:
        cam, m, n_lines, _ = CASES[name]
        app = Appearance(ball_level=0.05 if dark else 0.8, shading=False)
        (ball,) = estimate_image(_image(cam, m, n_lines, app, 0.6 if dark else 0.1), cam, m.radius_m, recipe=Recipe(method="paper")).balls
        out[name, dark] = ball
    return out


def _speed_err_pct(ball, m):
    return abs(ball.speed_mps - m.speed_mps) / m.speed_mps * 100


@pytest.mark.slow
@pytest.mark.parametrize(("name", "dark"), _KEYS, ids=[f"{n}-{'dark' if d else 'bright'}" for n, d in _KEYS])
def test_refinement_beats_initial_guess(paper_results, name, dark):
    """The refinement removes the key points' line-counting bias on V.x (paper Fig. 5).

    Per case the speed is held to a tolerance; that the refined speed is
    closer to the truth than the initial guess is asserted over the set
    (next test): the gradient energy is nearly flat along V.z (the depth
    axis, seen only through the slow change of apparent size), and Powell's
    line searches move along it by metres per second on noisy images
    (measured: +5.6 m/s on the 30-degree dark-ball case).
    """
    cam, m, n_lines, tol_pct = CASES[name]
    ball = paper_results[name, dark]
    vx_err = abs(ball.velocity_mps[0] - m.velocity_mps[0])
    vx_err0 = abs(ball.initial.velocity_mps[0] - m.velocity_mps[0])
    assert vx_err < vx_err0, f"refined V.x error {vx_err:.4f} not below initial {vx_err0:.4f} m/s"
    assert vx_err / m.velocity_mps[0] < 0.005
    assert _speed_err_pct(ball, m) < tol_pct
    assert ball.method == "paper" and ball.extra["evaluations"] > 10
    assert abs(ball.t_c_s - m.t_c_s) < 0.5 / cam.line_rate_hz
    assert ball.extra["energy"] < ball.extra["initial_energy"]


@pytest.mark.slow
def test_refined_speed_closer_to_truth_than_initial_guess(paper_results):
    """Paper Fig. 5 on untextured balls: the refined speed beats the initial guess.

    Measured: better in 6 of the 8 cases (the exceptions are the dark
    balls crossing perpendicularly, initial 0.298 % -> refined 0.306 %, and
    at 30 degrees, 0.57 % -> 1.53 %, both through V.z; the perpendicular one
    was refined to 0.11 % before the renderer sampled the balls' end lines
    finely: see the tolerance of CASES); the median error falls from 0.83 %
    to 0.08 %.
    """
    pairs = [
        (_speed_err_pct(paper_results[key], CASES[key[0]][1]), _speed_err_pct(paper_results[key].initial, CASES[key[0]][1]))
        for key in _KEYS
    ]
    better = sum(r < i for r, i in pairs)
    assert better >= 6, pairs
    refined, initial = np.median([r for r, _ in pairs]), np.median([i for _, i in pairs])
    assert refined < 0.25 * initial


@pytest.mark.slow
def test_textured_noisy_ball_found_and_measured():
    cam = LineScanCamera(2048, 3000.0, 1023.5, 50000.0)
    m = BallMotion(0.0335, 0.0015, (0, 0.02, 3.0), (30.0, 2.0, 0.0))
    app = Appearance(ball_level=0.65, texture="tennis", seam_level=0.95, orientation_seed=4)
    img = _image(cam, m, 150, app, 0.1, seed=9)
    (ball,) = estimate_image(img, cam, m.radius_m, recipe=Recipe(method="paper")).balls
    # found and measured in the sensor plane; V.z is the paper method's weak axis (see above)
    assert abs(ball.velocity_mps[0] - m.velocity_mps[0]) / m.velocity_mps[0] < 0.02
    assert abs(ball.velocity_mps[1] - m.velocity_mps[1]) < 0.5
    assert abs(ball.position_m[1] - m.position_m[1]) < 0.002
    assert abs(ball.position_m[2] - 3.0) < 0.2
