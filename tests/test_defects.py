"""Stuck sensor columns (ballscan.measure.defects): found on the ball, never elsewhere, repaired, and kept out of the edges."""

from __future__ import annotations

import numpy as np
import pytest

from ballscan.geometry.camera import LineScanCamera
from ballscan.geometry.motion import BallMotion
from ballscan.measure.defects import repaired_columns, repaired_image, stuck_columns
from ballscan.measure.detection import ColumnModel, detect
from ballscan.measure.edges import measure_edges
from ballscan.measure.images import LineImage
from ballscan.model.render import Appearance, SensorNoise, render
from ballscan.pipeline.estimate import estimate_image

CAM = LineScanCamera(2048, 3000.0, 1023.5, 50000.0, None)
RADIUS = 0.0335
#: 30 degrees oblique along the sensor: the limbs move across the columns during the passage
MOTION = BallMotion(RADIUS, 0.002, (0.0, 0.01, 3.0), (26.0, 15.0, 0.0))


@pytest.fixture(scope="module")
def rendered() -> tuple[np.ndarray, np.ndarray]:
    """An 8-bit render (sensor noise, 0.8 % PRNU) and the ball's largest coverage of each column."""
    r = render(CAM, (MOTION, Appearance.flat(0.8)), 200, background_level=0.2, noise=SensorNoise(), seed=3)
    return r.image.astype(float), r.coverage.max(axis=0)


def _with_column(data: np.ndarray, j: int, level_dn: float, seed: int = 0) -> LineImage:
    """``data`` with column ``j`` stuck at ``level_dn`` (plus 1 DN of read noise)."""
    out = data.copy()
    out[:, j] = np.clip(np.round(level_dn + np.random.default_rng(seed).normal(0.0, 1.0, out.shape[0])), 0, 255)
    return LineImage(out, 255.0, 8, "render")


def _ball_columns(contrast: np.ndarray) -> np.ndarray:
    return np.flatnonzero(contrast > 0.5 * contrast.max())


def test_no_column_is_stuck_on_a_clean_sensor(rendered):
    img = LineImage(rendered[0], 255.0, 8, "render")
    assert stuck_columns(img, detect(img)).size == 0


@pytest.mark.parametrize(("where", "level_dn"), [("middle", 3.0), ("middle", 240.0), (2, 3.0), (2, 240.0), (-3, 3.0), (-3, 240.0)])
def test_a_dead_or_hot_column_under_the_ball_is_found(rendered, where, level_dn):
    cols = _ball_columns(rendered[1])
    j = int(cols[cols.size // 2]) if where == "middle" else int(cols[where])
    img = _with_column(rendered[0], j, level_dn)
    assert stuck_columns(img, detect(img)).tolist() == [j]


def test_a_stuck_column_away_from_the_ball_is_left_alone(rendered):
    cols = _ball_columns(rendered[1])
    img = _with_column(rendered[0], int(cols.min()) - 300, 3.0)
    # the column hides nothing of the ball: nothing to repair
    assert stuck_columns(img, detect(img)).size == 0


@pytest.mark.parametrize("offset_dn", [-40.0, 40.0])
def test_a_backdrop_line_beside_the_ball_is_not_taken_for_a_stuck_column(rendered, offset_dn):
    cols = _ball_columns(rendered[1])
    data = rendered[0].copy()
    for j in (int(cols.min()) - 2, int(cols.max()) + 2):  # just outside the outline, on every line
        data[:, j] = np.clip(data[:, j] + offset_dn, 0, 255)
    img = LineImage(data, 255.0, 8, "render")
    assert stuck_columns(img, detect(img)).size == 0


def test_two_stuck_columns_side_by_side_are_both_found(rendered):
    cols = _ball_columns(rendered[1])
    j = int(cols[cols.size // 2])
    img = _with_column(rendered[0], j, 3.0)
    img = _with_column(img.data, j + 1, 3.0, seed=1)
    assert stuck_columns(img, detect(img)).tolist() == [j, j + 1]


def test_repair_is_the_neighbours_linear_interpolation():
    data = np.arange(40.0).reshape(4, 10) ** 1.5
    img = LineImage(data, 1e6, 16, "x")
    out = repaired_image(img, np.array([0, 4, 5, 9]))
    np.testing.assert_array_equal(out.data[:, 0], data[:, 1])
    np.testing.assert_array_equal(out.data[:, 9], data[:, 8])
    np.testing.assert_allclose(out.data[:, 4], data[:, 3] + (data[:, 6] - data[:, 3]) / 3)
    np.testing.assert_allclose(out.data[:, 5], data[:, 3] + 2 * (data[:, 6] - data[:, 3]) / 3)
    np.testing.assert_array_equal(np.delete(out.data, [0, 4, 5, 9], axis=1), np.delete(data, [0, 4, 5, 9], axis=1))
    np.testing.assert_array_equal(img.data, np.arange(40.0).reshape(4, 10) ** 1.5)  # the input is not touched
    assert (out.saturation_dn, out.bits, out.source) == (img.saturation_dn, img.bits, img.source)
    model = repaired_columns(ColumnModel(np.array([10.0, 12.0, 200.0, 16.0]), np.array([1.0, 1.0, 0.2, 1.0])), np.array([2]))
    np.testing.assert_allclose(model.background_dn, [10.0, 12.0, 14.0, 16.0])
    np.testing.assert_allclose(model.noise_dn, [1.0, 1.0, 1.0, 1.0])


def test_no_edge_is_read_through_a_blind_column(rendered):
    img = LineImage(rendered[0], 255.0, 8, "render")
    det = detect(img)
    t = np.arange(img.data.shape[0]) / CAM.line_rate_hz
    region = det.regions[0]
    free = measure_edges(img.data, region, det.background_dn, det.noise_dn, t, saturation_dn=255.0)
    left = np.flatnonzero(free.left_ok)
    j = int(round(free.left_px[left[left.size // 2]]))
    blind = measure_edges(img.data, region, det.background_dn, det.noise_dn, t, saturation_dn=255.0, blind_columns=(j,))
    # an edge inside pixel j is read through it; windows (3 px here) end 3 px away
    near, far = np.abs(free.left_px - j) < 0.5, ~(np.abs(free.left_px - j) < 3.0)
    assert np.any(near & free.left_ok) and not np.any(near & blind.left_ok)
    np.testing.assert_array_equal(blind.left_ok[far], free.left_ok[far])
    # the edges kept are the same measurements
    keep = blind.left_ok
    assert keep.sum() >= 0.5 * free.left_ok.sum()
    np.testing.assert_array_equal(blind.left_px[keep], free.left_px[keep])
    np.testing.assert_array_equal(blind.right_ok, free.right_ok)


@pytest.mark.parametrize("where", ["middle", 1, 2, 3, -2, -3])
def test_a_ball_crossed_by_a_dead_column_is_measured_as_without_it(rendered, where):
    clean = estimate_image(LineImage(rendered[0], 255.0, 8, "render"), CAM, RADIUS).balls
    cols = _ball_columns(rendered[1])
    j = int(cols[cols.size // 2]) if where == "middle" else int(cols[where])
    balls = estimate_image(_with_column(rendered[0], j, 3.0), CAM, RADIUS).balls
    assert len(clean) == len(balls) == 1
    b, c = balls[0], clean[0]
    assert b.extra["repaired_columns"] == [j] and "repaired_columns" not in c.extra
    # the repaired image's estimate uses a subset of the clean one's edges:
    # their difference has the sigma sqrt(sb^2 - sc^2) (floored at a tenth of
    # sc); within 3 of it (unrepaired, with no edge dropped: 2.7 sc off with
    # the column in the middle, 100 sc at the limb), and of the truth within 3 sb
    def nested(vb, vc, sb, sc):
        return abs(vb - vc) < 3.0 * np.sqrt(max(sb**2 - sc**2, (0.1 * sc) ** 2))

    assert nested(b.speed_mps, c.speed_mps, b.speed_sigma_mps, c.speed_sigma_mps)
    assert abs(b.speed_mps - MOTION.speed_mps) < 3 * b.speed_sigma_mps
    for k in (0, 1):
        assert nested(b.velocity_mps[k], c.velocity_mps[k], b.velocity_sigma_mps[k], c.velocity_sigma_mps[k])
