"""Rig geometry: the rig file, a world motion's view in each camera (with its Jacobian), viewing planes and their crossing."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from ballscan.errors import CameraFileError
from ballscan.geometry.camera import LineScanCamera, save_camera
from ballscan.geometry.rig import (
    Rig,
    RigCamera,
    WorldMotion,
    camera_params,
    load_rig,
    plane_crossing,
    rig_from_dict,
    save_rig,
    turned_camera,
    viewing_plane,
    world_crossing,
)
from ballscan.lab.rig import RIG_PRESETS, camera_about_lane

from .conftest import random_rotation

CAM = LineScanCamera(width=2048, focal_px=4000.0, principal_px=1023.5, line_rate_hz=70000.0)
GRAVITY = np.array([0.0, 0.0, -9.81])


def _numeric_jacobian(state, camera, t_ref, g, off, h=1e-6):
    J = np.zeros((6, 6))
    for i in range(6):
        sp, sm = state.copy(), state.copy()
        sp[i] += h
        sm[i] -= h
        J[:, i] = (camera_params(sp, camera, t_ref, g, off)[0] - camera_params(sm, camera, t_ref, g, off)[0]) / (2 * h)
    return J


@settings(max_examples=25, deadline=None, derandomize=True)
@given(seed=st.integers(0, 10_000), gravity=st.booleans())
def test_camera_params_jacobian_matches_differences(seed, gravity):
    rng = np.random.default_rng(seed)
    R = random_rotation(rng)
    cam = CAM.with_pose(R, rng.normal(size=3))
    # a ball crossing the plane (its velocity with a component along the plane's normal)
    V = rng.normal(size=3) * 20.0 + R[0] * 30.0
    state = np.concatenate([rng.normal(size=3) * 0.5, V])
    g = GRAVITY if gravity else np.zeros(3)
    theta, J, ok = camera_params(state, cam, 0.01, g, 2e-4)
    assert ok
    scale = np.array([1e-6, 1e-4, 1e-4, 1e-3, 1e-3, 1e-3])
    Jn = _numeric_jacobian(state, cam, 0.01, g, 2e-4)
    assert np.all(np.abs(J - Jn) <= 1e-5 * (1 + np.abs(Jn)) + scale[:, None] * 1e-3)


def test_camera_params_put_the_centre_on_the_viewing_plane_at_the_crossing():
    p = RIG_PRESETS["tee"]
    for rc in p.rig.cameras:
        theta, _, ok = camera_params(p.motion.state, rc.camera, p.motion.t_ref_s, GRAVITY, 3e-4)
        assert ok
        t_rig = theta[0] - 3e-4
        X = p.motion.centre(t_rig)
        pc = rc.camera.world_to_camera(X)
        assert abs(pc[0]) < 1e-12
        np.testing.assert_allclose(pc[1:], theta[1:3], atol=1e-12)
        np.testing.assert_allclose(rc.camera.vectors_to_world(theta[3:]), p.motion.velocity_at(t_rig), atol=1e-10)


def test_world_crossing_with_gravity_is_the_parabola_root():
    cam = camera_about_lane(CAM, 3.0, 0.0, 0.5)
    state = np.array([0.0, 0.0, 0.0, 10.0, 0.0, 5.0])
    t, X, V, _, ok = world_crossing(state, cam, 0.0, GRAVITY)
    assert ok and t == pytest.approx(0.05, rel=1e-12)  # X = 10 t reaches the plane X = 0.5
    np.testing.assert_allclose(X, [0.5, 0.0, 5.0 * 0.05 - 0.5 * 9.81 * 0.05**2], atol=1e-12)
    # a plane the path crosses only through gravity's curvature: nearest root taken
    up = camera_about_lane(CAM, 3.0, 0.0, 0.0).with_pose(np.array([[0, 0, 1.0], [0, 1.0, 0], [-1.0, 0, 0]]), np.array([-1.0, 0, 3.0]))
    t2, X2, _, _, ok2 = world_crossing(state, up, 0.0, GRAVITY)  # plane Z = 1 (normal +Z)
    assert ok2 and X2[2] == pytest.approx(1.0, abs=1e-12)
    assert t2 == pytest.approx((5.0 - math.sqrt(25 - 2 * 9.81)) / 9.81, rel=1e-12)


def test_world_motion_round_trip_and_in_camera():
    p = RIG_PRESETS["lane-90"]
    m = p.motion
    assert WorldMotion.from_dict(m.to_dict()) == m
    later = m.at(m.t_ref_s + 0.002)
    np.testing.assert_allclose(later.centre(m.t_ref_s), m.position_m, atol=1e-15)
    cm = m.in_camera(p.rig.cameras[1])
    assert cm.position_m[0] == 0.0 and cm.t_c_s == pytest.approx(m.t_ref_s)
    with pytest.raises(ValueError, match="unknown"):
        m.in_camera(RigCamera("c", p.rig.cameras[0].camera, None))


def test_rig_file_round_trip(tmp_path):
    rig = RIG_PRESETS["lane-30"].rig
    rig = rig.with_camera(1, RigCamera("oblique", rig.cameras[1].camera, None, 2e-3))
    path = tmp_path / "r.rig.toml"
    save_rig(rig, path)
    back = load_rig(path)
    assert back.names == rig.names and back.gravity_mps2 == rig.gravity_mps2
    assert back.cameras[1].clock_offset_s is None and back.cameras[1].clock_sigma_s == 2e-3
    assert back.unknown_clocks == (1,) and back.reference == 0
    for a, b in zip(back.cameras, rig.cameras):
        np.testing.assert_allclose(a.camera.rotation_matrix, b.camera.rotation_matrix, atol=1e-15)
        assert a.camera.gravity_mps2 == rig.gravity_mps2


def test_rig_file_refers_to_camera_files(tmp_path):
    save_camera(CAM, tmp_path / "a.toml")
    text = """
gravity_mps2 = [0, 0, -9.81]
[[camera]]
name = "a"
file = "a.toml"
[camera.pose]
rotation = [[1, 0, 0], [0, 0, -1], [0, 1, 0]]
translation = [0, 0, 4]
[[camera]]
name = "b"
file = "a.toml"
clock_offset_s = "unknown"
[camera.pose]
rotation = [[1, 0, 0], [0, -1, 0], [0, 0, -1]]
translation = [0, 0, 4]
"""
    (tmp_path / "r.toml").write_text(text)
    rig = load_rig(tmp_path / "r.toml")
    assert rig.cameras[0].camera.width == 2048 and rig.cameras[1].clock_offset_s is None
    assert rig.cameras[1].camera.gravity_mps2 == (0.0, 0.0, -9.81)


@pytest.mark.parametrize(
    "text, key",
    [
        ("[[camera]]\nname='a'\nwidth=10\nfocal_px=1.0\nprincipal_px=4.5\nline_rate_hz=1.0\n", "pose"),
        ("speed = 3\n", "speed"),
        ("", "camera"),
        ("[[camera]]\nname='a'\nclock_offset_s='late'\n", "clock_offset_s"),
        ("[[camera]]\nname='a'\nfile='missing.toml'\n", None),
    ],
)
def test_bad_rig_files_name_the_file_and_key(tmp_path, text, key):
    path = tmp_path / "bad.toml"
    path.write_text(text)
    with pytest.raises(CameraFileError) as err:
        load_rig(path)
    msg = str(err.value)
    assert "\n" not in msg and ("bad.toml" in msg or "missing.toml" in msg)
    if key:
        assert key in msg


@pytest.mark.parametrize(
    "content, match",
    [
        (b"gravity_mps2 = [0.0, 0.0, -9.81]\n" + b"# padding\n" * 200_000, "not a rig file"),
        (b"x = " + b"[" * 5000 + b"]" * 5000 + b"\n", "nested too deeply"),
        (b"\x89PNG\r\n\x1a\n\xff\xfe", "not a rig file \\(not UTF-8 text\\)"),
        (b"x = " + b"9" * 5000 + b"\n", "not valid TOML"),
        (b"speed = = 3", "not valid TOML"),
    ],
)
def test_unreadable_rig_files_are_refused_as_camera_files_are(tmp_path, content, match):
    path = tmp_path / "rig.toml"
    path.write_bytes(content)
    with pytest.raises(CameraFileError, match=match) as err:
        load_rig(path)
    assert str(path) in str(err.value)


def test_rig_needs_a_known_clock_and_distinct_names():
    cam = camera_about_lane(CAM, 4.0, 0.0)
    with pytest.raises(CameraFileError, match="known clock"):
        Rig((RigCamera("a", cam, None), RigCamera("b", cam, None)))
    with pytest.raises(CameraFileError, match="twice"):
        Rig((RigCamera("a", cam), RigCamera("a", cam)))
    with pytest.raises(CameraFileError, match="pose"):
        RigCamera("a", CAM)
    with pytest.raises(CameraFileError):
        rig_from_dict({"camera": [{"name": "a"}]}, "x.toml")


def test_viewing_planes_and_their_crossing():
    a = viewing_plane(camera_about_lane(CAM, 4.0, 0.0))
    b = viewing_plane(camera_about_lane(CAM, 4.0, 90.0, 0.2))
    np.testing.assert_allclose(a.normal, [1, 0, 0], atol=1e-15)
    np.testing.assert_allclose(a.centre_m, [0, -4, 0], atol=1e-12)
    x = plane_crossing(a, b)
    assert x.parallel and x.distance_m == pytest.approx(0.2) and x.axes_angle_deg == pytest.approx(90.0)
    # a camera whose plane is turned 30 degrees about world Z: the planes meet along Z
    Rz = np.array([[math.cos(0.5236), math.sin(0.5236), 0], [-math.sin(0.5236), math.cos(0.5236), 0], [0, 0, 1.0]])
    cam_c = CAM.with_pose(camera_about_lane(CAM, 4.0, 0.0).rotation_matrix @ Rz.T, np.array([0.0, 0.0, 4.0]))
    c = viewing_plane(cam_c)
    x2 = plane_crossing(a, c)
    assert not x2.parallel and x2.angle_deg == pytest.approx(30.0, abs=1e-3)
    assert abs(abs(x2.direction[2]) - 1.0) < 1e-12
    for p in (a, c):
        assert p.normal @ x2.point_m == pytest.approx(p.offset_m, abs=1e-12)


def test_turned_camera_keeps_the_plane_and_the_distance():
    cam = camera_about_lane(CAM, 4.0, 0.0)
    point = np.array([0.0, 0.1, -0.05])
    for a in (10.0, 90.0, 200.0):
        t = turned_camera(cam, point, a)
        pa, pt = viewing_plane(cam), viewing_plane(t)
        np.testing.assert_allclose(pt.normal, pa.normal, atol=1e-12)
        assert pt.offset_m == pytest.approx(pa.offset_m, abs=1e-12)
        assert np.linalg.norm(pt.centre_m - point) == pytest.approx(np.linalg.norm(pa.centre_m - point))
        assert math.degrees(math.acos(np.clip(pa.axis @ pt.axis, -1, 1))) == pytest.approx(min(a, 360 - a))
    np.testing.assert_allclose(turned_camera(cam, point, 0.0).rotation_matrix, cam.rotation_matrix, atol=1e-15)
