"""Camera model: projection, distortion, frames, Eq. (1), TOML I/O and its errors."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from ballscan.geometry.camera import (
    LineScanCamera,
    camera_from_eq1,
    crop_camera,
    line_times,
    load_camera,
    save_camera,
)
from ballscan.errors import CameraFileError, GeometryError

from .conftest import random_rotation


def make(**kw):
    base = dict(width=2048, focal_px=3000.0, principal_px=1023.5, line_rate_hz=50000.0)
    base.update(kw)
    return LineScanCamera(**base)


def test_project_pinhole_formula():
    cam = make()
    y, z = np.array([0.1, -0.2, 0.0]), np.array([2.0, 4.0, 1.0])
    np.testing.assert_allclose(cam.project(y, z), 1023.5 + 3000.0 * y / z, rtol=0, atol=1e-12)


@pytest.mark.parametrize("k1,k2", [(0.0, 0.0), (-0.08, 0.0), (0.05, -0.02), (-0.1, 0.03)])
def test_backproject_round_trip_with_distortion(k1, k2):
    cam = make(k1=k1, k2=k2)
    u = np.linspace(0, cam.width - 1, 501)
    n = cam.backproject(u)
    np.testing.assert_allclose(cam.project_normalised(n), u, rtol=0, atol=1e-9)


def test_distortion_moves_edge_pixels():
    plain, dist = make(), make(k1=-0.1)
    n = plain.backproject(np.array([0.0, 2047.0]))
    assert np.all(np.abs(dist.project_normalised(n) - np.array([0.0, 2047.0])) > 0.1)


def test_distort_derivative_matches_finite_difference():
    cam = make(k1=-0.07, k2=0.02)
    n = np.linspace(-0.4, 0.4, 41)
    h = 1e-6
    fd = (cam.distort(n + h) - cam.distort(n - h)) / (2 * h)
    np.testing.assert_allclose(cam.distort_derivative(n), fd, rtol=1e-7, atol=1e-9)


def test_project_behind_camera_is_an_error():
    with pytest.raises(GeometryError):
        make().project(np.array([0.0]), np.array([-1.0]))


def test_line_times_uniform_and_timestamps():
    cam = make(line_rate_hz=1000.0)
    np.testing.assert_allclose(line_times(cam, 4), [0, 1e-3, 2e-3, 3e-3])
    ts = np.array([0.0, 0.001, 0.0025, 0.003])
    np.testing.assert_array_equal(line_times(cam, 4, ts), ts)
    with pytest.raises(ValueError, match="strictly increasing"):
        line_times(cam, 3, np.array([0.0, 0.0, 1.0]))
    with pytest.raises(ValueError, match="expected 3"):
        line_times(cam, 3, np.array([0.0, 1.0]))


def test_exposure_defaults_to_line_period():
    assert make(line_rate_hz=2000.0).exposure == pytest.approx(5e-4)
    assert make(exposure_s=1e-5).exposure == 1e-5


def test_world_camera_round_trip():
    rng = np.random.default_rng(1)
    cam = make().with_pose(random_rotation(rng), rng.normal(size=3))
    p = rng.normal(size=(10, 3))
    np.testing.assert_allclose(cam.camera_to_world(cam.world_to_camera(p)), p, atol=1e-12)
    v = rng.normal(size=(5, 3))
    np.testing.assert_allclose(cam.vectors_to_world(cam.vectors_to_camera(v)), v, atol=1e-12)


def test_gravity_carried_to_camera_frame():
    R = np.array([[1.0, 0, 0], [0, 0, -1.0], [0, 1.0, 0]])
    cam = make().with_pose(R, [0, 0, 0])
    cam = LineScanCamera(**{**cam.__dict__, "gravity_mps2": (0.0, 0.0, -9.81)})
    np.testing.assert_allclose(cam.gravity_camera_mps2(), [0.0, 9.81, 0.0], atol=1e-12)


# ---------------------------------------------------------------- Eq. (1)


def _eq1_consistent(cam: LineScanCamera, rng: np.random.Generator) -> None:
    """Eq. (1) of the camera maps world points of its viewing plane like the camera does."""
    e = cam.to_eq1()
    # points of the viewing plane in the camera frame, in front of the camera
    pts_c = np.column_stack([np.zeros(20), rng.uniform(-1, 1, 20), rng.uniform(1, 5, 20)])
    pts_w = cam.camera_to_world(pts_c)
    np.testing.assert_allclose(e.plane_x(pts_w[:, 1], pts_w[:, 2]), pts_w[:, 0], atol=1e-9)
    y_paper = e.image_coordinate(pts_w[:, 1], pts_w[:, 2])
    np.testing.assert_allclose(y_paper, -cam.focal_px * pts_c[:, 1] / pts_c[:, 2], atol=1e-7)


@settings(max_examples=60, deadline=None)
@given(seed=st.integers(0, 2**32 - 1))
def test_eq1_round_trip_random_poses(seed):
    rng = np.random.default_rng(seed)
    R = random_rotation(rng)
    t = rng.normal(scale=2.0, size=3)
    cam = make().with_pose(R, t)
    try:
        e = cam.to_eq1()
    except GeometryError:
        # Eq. (1) is undefined here; the test of that branch is below
        return
    if abs(R[0, 0]) < 1e-3:
        return  # badly conditioned; covered by the error test
    _eq1_consistent(cam, rng)
    # the plane point (r, 0, 0) decides the half-turn ambiguity
    depth = cam.world_to_camera(np.array([e.r, 0.0, 0.0]))[2]
    back = camera_from_eq1(
        e, width=cam.width, focal_px=cam.focal_px, principal_px=cam.principal_px,
        line_rate_hz=cam.line_rate_hz, origin_in_front=bool(depth > 0),
    )
    np.testing.assert_allclose(back.rotation_matrix, R, atol=1e-7)
    np.testing.assert_allclose(back.translation_vector, t, atol=1e-7)


def test_eq1_identity_pose_values():
    cam = make().with_pose(np.eye(3), [0.0, 0.0, 2.0])
    e = cam.to_eq1()
    # viewing plane is X = 0; y' = -f Y / (Z + 2) -> n1 = -f/2, n5 = 1/2
    assert (e.p, e.q, e.r) == (0.0, 0.0, 0.0)
    assert e.n1 == pytest.approx(-1500.0) and e.n5 == pytest.approx(0.5)
    assert e.n2 == pytest.approx(0.0) and e.n3 == pytest.approx(0.0) and e.n4 == pytest.approx(0.0)


def test_eq1_undefined_poses_raise():
    # identity pose at the origin: the world origin is the projection centre
    with pytest.raises(GeometryError, match="constant term"):
        make().with_pose(np.eye(3), [0.0, 0.0, 0.0]).to_eq1()
    # viewing plane parallel to world X (camera x axis = world Y)
    R = np.array([[0.0, 1.0, 0.0], [-1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
    with pytest.raises(GeometryError, match="parallel"):
        make().with_pose(R, [0, 0, 1.0]).to_eq1()


# ---------------------------------------------------------------- TOML I/O

GOOD = """
width = 2048
focal_px = 2500.0
principal_px = 1023.5
line_rate_hz = 70000.0
exposure_s = 1.0e-5
k1 = -0.01
crossing = "+x"
gravity_mps2 = [0.0, 0.0, -9.81]
[pose]
rotation = [[1, 0, 0], [0, 0, -1], [0, 1, 0]]
translation = [0.0, 0.5, 3.0]
"""


def test_toml_round_trip(tmp_path):
    p = tmp_path / "cam.toml"
    p.write_text(GOOD)
    cam = load_camera(p)
    assert cam.width == 2048 and cam.crossing == "+x" and cam.has_pose
    out = tmp_path / "out.toml"
    save_camera(cam, out, comment="written by a test")
    assert load_camera(out) == cam


def test_shared_scene_cameras_load():
    from .conftest import DATA

    files = sorted((DATA / "scenes").glob("*.camera.toml"))
    assert files, "reference scene cameras missing from tests/data/scenes"
    for f in files:
        assert load_camera(f).width in (1024, 2048)


BAD = [
    ("width = 2048\nfocal_px = 2500.0\nprincipal_px = 1023.5\n", "line_rate_hz", "missing"),
    ("width = 2048\nfocal_px = nan\nprincipal_px = 1023.5\nline_rate_hz = 1e4\n", "focal_px", "finite"),
    ("width = 2048\nfocal_px = -5.0\nprincipal_px = 1023.5\nline_rate_hz = 1e4\n", "focal_px", "positive"),
    ("width = \"wide\"\nfocal_px = 5.0\nprincipal_px = 1023.5\nline_rate_hz = 1e4\n", "width", "number"),
    ("width = 2048.5\nfocal_px = 5.0\nprincipal_px = 1023.5\nline_rate_hz = 1e4\n", "width", "whole"),
    ("width = 2048\nfocal_px = 5.0\nprincipal_px = 1023.5\nline_rate_hz = 1e4\nexposure_s = 1.0\n", "exposure_s", "exceeds"),
    ("width = 2048\nfocal_px = 5.0\nprincipal_px = 1023.5\nline_rate_hz = 1e4\ncrossing = \"up\"\n", "crossing", "+x"),
    ("width = 2048\nfocal_px = 2500.0\nprincipal_px = 1023.5\nline_rate_hz = 1e4\n[pose]\nrotation = [[1,0,0],[0,1,0],[0,0.5,1]]\ntranslation = [0,0,0]\n", "pose.rotation", "rotation"),
    ("width = 2048\nfocal_px = 2500.0\nprincipal_px = 1023.5\nline_rate_hz = 1e4\n[pose]\nrotation = [[1,0,0],[0,1,0]]\ntranslation = [0,0,0]\n", "pose.rotation", "shape"),
    ("width = 2048\nfocal_px = 2500.0\nprincipal_px = 1023.5\nline_rate_hz = 1e4\ngravity_mps2 = [0, 0, -9.81]\n", "gravity_mps2", "pose"),
    ("width = 2048\nfocal_px = 2500.0\nprincipal_px = 1023.5\nline_rate_hz = 1e4\nfocus = 3\n", "focus", "unknown"),
    ("width = 2048\nfocal_px = 2500.0\nprincipal_px = 1023.5\nline_rate_hz = 1e4\nk1 = -5.0\n", "k1", "monotonic"),
    # values no camera has: refused at load, before an estimate could overflow or run for minutes on them
    ("width = 2048\nfocal_px = 2500.0\nprincipal_px = 1023.5\nline_rate_hz = 1e300\n", "line_rate_hz", "outside the range"),
    ("width = 2048\nfocal_px = 2500.0\nprincipal_px = 1023.5\nline_rate_hz = 1e-9\n", "line_rate_hz", "outside the range"),
    ("width = 2048\nfocal_px = 1e300\nprincipal_px = 1023.5\nline_rate_hz = 1e4\n", "focal_px", "outside the range"),
    ("width = 2048\nfocal_px = 0.001\nprincipal_px = 1023.5\nline_rate_hz = 1e4\n", "focal_px", "outside the range"),
    ("width = 20000000000\nfocal_px = 2500.0\nprincipal_px = 1023.5\nline_rate_hz = 1e4\n", "width", "outside the range"),
    ("width = 2048\nfocal_px = 2500.0\nprincipal_px = -1e300\nline_rate_hz = 1e4\n", "principal_px", "sensor widths"),
    ("width = 2048\nfocal_px = 2500.0\nprincipal_px = 1023.5\nline_rate_hz = 1e4\nk1 = 1e300\n", "k1", "outside the range"),
    ("width = 2048\nfocal_px = 2500.0\nprincipal_px = 1023.5\nline_rate_hz = 1e4\nexposure_s = 1e-300\n", "exposure_s", "shorter"),
    ("width = 2048\nfocal_px = 2500.0\nprincipal_px = 1023.5\nline_rate_hz = 1e4\nexposure_s = -1e-5\n", "exposure_s", "positive"),
    ("width = 2048\nfocal_px = 2500.0\nprincipal_px = 1023.5\nline_rate_hz = -inf\n", "line_rate_hz", "finite"),
    ("width = 2048\nfocal_px = 2500.0\nprincipal_px = 1023.5\nline_rate_hz = 1e4\n[pose]\nrotation = [[1,0,0],[0,1,0],[0,0,1]]\ntranslation = [0,0,1e300]\n", "pose.translation", "origin"),
    ("width = 2048\nfocal_px = 2500.0\nprincipal_px = 1023.5\nline_rate_hz = 1e4\ngravity_mps2 = [0, 0, -1e300]\n[pose]\nrotation = [[1,0,0],[0,1,0],[0,0,1]]\ntranslation = [0,0,0]\n", "gravity_mps2", "m/s^2"),
]


@pytest.mark.parametrize("text,key,word", BAD)
def test_bad_camera_files_give_one_line_errors(tmp_path, text, key, word):
    p = tmp_path / "bad.toml"
    p.write_text(text)
    with pytest.raises(CameraFileError) as info:
        load_camera(p)
    msg = str(info.value)
    assert "\n" not in msg
    assert str(p) in msg and key in msg and word in msg


def test_unparseable_and_missing_files(tmp_path):
    p = tmp_path / "x.toml"
    p.write_text("width = = 3")
    with pytest.raises(CameraFileError, match="not valid TOML"):
        load_camera(p)
    with pytest.raises(CameraFileError, match="not found"):
        load_camera(tmp_path / "nope.toml")
    binary = tmp_path / "image.png"
    binary.write_bytes(b"\x89PNG\r\n\x1a\n\xff\xfe")
    with pytest.raises(CameraFileError, match=r"image.png: not a camera file \(not UTF-8 text\)"):
        load_camera(binary)
    with pytest.raises(CameraFileError, match="cannot read"):
        load_camera(tmp_path)  # a folder


@pytest.mark.parametrize("nest", ["[" * 5000 + "]" * 5000, "{a = " * 5000 + "1" + "}" * 5000])
def test_a_file_nested_5000_deep_is_a_clean_error(tmp_path, nest):
    p = tmp_path / "deep.toml"
    p.write_text("width = 2048\nfocal_px = 2500.0\nprincipal_px = 1023.5\nline_rate_hz = 1e4\nx = " + nest + "\n")
    with pytest.raises(CameraFileError, match="nested too deeply") as info:
        load_camera(p)
    assert str(p) in str(info.value)


def test_a_huge_file_is_refused_before_it_is_parsed(tmp_path):
    p = tmp_path / "big.toml"
    p.write_text("width = 2048\n" + "# padding\n" * 200_000)
    with pytest.raises(CameraFileError, match="not a camera file"):
        load_camera(p)


def test_crop_camera_equals_a_validated_replace():
    cam = LineScanCamera(width=512, focal_px=1100.0, principal_px=255.5, line_rate_hz=20000.0, k1=-0.02, k2=0.004, crossing="-x")
    for c0, c1, exp in ((0, 512, None), (100, 300, None), (0, 40, 1.0 / cam.line_rate_hz), (470, 512, 2e-5)):
        got = crop_camera(cam, c0, c1, exposure_s=exp)
        changes = {} if (c0, c1) == (0, 512) else {"width": c1 - c0, "principal_px": cam.principal_px - c0}
        if exp is not None:
            changes["exposure_s"] = exp
        assert got == replace(cam, **changes)
        assert got.source == cam.source
    assert crop_camera(cam, 0, 512) is cam
    # what a validation refuses is still refused
    with pytest.raises(ValueError, match="exposure_s"):
        crop_camera(cam, 10, 20, exposure_s=2.0 / cam.line_rate_hz)
    with pytest.raises(ValueError, match="width"):
        crop_camera(cam, 10, 11)
