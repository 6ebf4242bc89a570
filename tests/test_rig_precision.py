"""The joint Cramér–Rao bound of a rig (solve.rig_precision)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from ballscan.geometry.rig import WorldMotion
from ballscan.lab.rig import RIG_PRESETS, rig_for_angle
from ballscan.pipeline.rig import single_camera_rig
from ballscan.solve.constraint import Constraint
from ballscan.solve.precision import edge_crlb
from ballscan.solve.rig_precision import direction_sigma_deg, rig_crlb, sweep_second_camera

from ballscan.geometry.camera import LineScanCamera
from ballscan.geometry.motion import BallMotion
from ballscan.model.silhouette import visible_line_count

LANE = RIG_PRESETS["lane-90"]


def test_one_camera_without_pose_is_its_own_bound():
    cam = LineScanCamera(width=2048, focal_px=4000.0, principal_px=1023.5, line_rate_hz=70000.0)
    m = BallMotion(0.0335, 0.0, (0.0, 0.05, 4.0), (44.0, 4.0, -3.0))
    rig = single_camera_rig(cam)
    b = rig_crlb(rig, WorldMotion(0.0335, 0.0, m.position_m, m.velocity_mps), edge_noise_px=0.1)
    # the rig's bound puts the crossing at the same line phase as `ballscan precision` does
    t_c = (0.6 * visible_line_count(cam, m) + 5.0) / cam.line_rate_hz
    probe = edge_crlb(cam, BallMotion(0.0335, t_c, m.position_m, m.velocity_mps), 0.1)
    np.testing.assert_allclose(b.covariance[4:, 4:], probe.covariance[3:, 3:], rtol=1e-6)
    np.testing.assert_allclose(b.covariance[2:4, 2:4], probe.covariance[1:3, 1:3], rtol=1e-6)
    assert b.covariance[1, 1] == 0.0  # the crossing lies on the plane x = 0


def test_two_cameras_pin_what_each_alone_cannot():
    b = rig_crlb(LANE.rig, LANE.motion, edge_noise_px=0.1)
    joint = math.sqrt(np.linalg.eigvalsh(b.covariance[4:, 4:]).max())
    for c in b.per_camera.values():
        assert joint * 100 < math.sqrt(c[5, 5])  # each camera's depth velocity
    assert b.direction_sigma_deg < 0.1
    assert b.direction_sigma_deg >= max(b.elevation_sigma_deg, b.azimuth_sigma_deg * math.cos(math.radians(6.5))) * 0.999
    assert b.to_dict()["covariance"]["parameters"][0] == "t_c_s"
    assert "joint" in b.to_text()


def test_direction_sigma_of_an_isotropic_covariance():
    V = np.array([10.0, 0.0, 0.0])
    assert direction_sigma_deg(V, np.eye(3) * 0.01) == pytest.approx(math.degrees(0.1 / 10.0))


def test_sweep_narrows_towards_ninety_degrees():
    rows = sweep_second_camera(LANE.rig, LANE.motion, [10.0, 30.0, 60.0, 90.0], edge_noise_px=0.1)
    s = [b.direction_sigma_deg for _, b in rows]
    assert all(a > b for a, b in zip(s, s[1:]))
    # a turn of 90 degrees about the path reproduces the preset's second camera (up to the turn's sense)
    direct = rig_crlb(rig_for_angle(90.0), LANE.motion, edge_noise_px=0.1)
    assert s[-1] == pytest.approx(direct.direction_sigma_deg, rel=0.05)


def test_unknown_clock_and_constraint_enter_the_bound():
    from dataclasses import replace

    rig = LANE.rig.with_camera(1, replace(LANE.rig.cameras[1], clock_offset_s=None))
    b = rig_crlb(rig, LANE.motion, edge_noise_px=0.1)
    assert 0 < b.clock_sigma_s["top"] < 1e-5
    known = rig_crlb(LANE.rig, LANE.motion, edge_noise_px=0.1)
    assert np.all(b.sigmas[4:] >= known.sigmas[4:] * (1 - 1e-9))
    one = single_camera_rig(LANE.rig.cameras[0].camera)
    free = rig_crlb(one, LANE.motion, edge_noise_px=0.1)
    # the ball's path through a known point 2 m down the lane, within 1 cm: the depth velocity pinned
    P = np.asarray(LANE.motion.centre(LANE.motion.t_ref_s + 2.0 / 44.6))
    pinned = rig_crlb(one, LANE.motion, edge_noise_px=0.1, constraint=Constraint("point", point_m=tuple(P), sigma_m=0.01))
    assert pinned.direction_sigma_deg * 5 < free.direction_sigma_deg


def test_a_ball_that_misses_a_camera_is_refused():
    m = WorldMotion(0.0335, 0.0, (0.0, 0.0, 0.0), (0.0, 10.0, 0.0))  # along the plane: never crosses
    with pytest.raises(ValueError, match="does not cross"):
        rig_crlb(LANE.rig, m)
