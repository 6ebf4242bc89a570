"""The lens model (ballscan.geometry.lens): its slope against finite differences, the round trip, and its compiled twins."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from numba import njit

from ballscan.errors import GeometryError
from ballscan.geometry.camera import LineScanCamera
from ballscan.geometry.lens import distorted, distortion_slope, normalised, project, undistorted

LENSES = [(0.0, 0.0), (-0.05, 0.01), (-0.4, 0.0), (0.1, -0.02)]


@njit
def _compiled_forms(n, u, focal_px, principal_px, k1, k2):
    m, ok = normalised(u, focal_px, principal_px, k1, k2)
    return distorted(n, k1, k2), distortion_slope(n, k1, k2), project(n, focal_px, principal_px, k1, k2), m, ok


@pytest.mark.parametrize("k1, k2", LENSES)
def test_distortion_slope_equals_the_finite_difference(k1, k2):
    n = np.linspace(-0.3, 0.3, 61)
    h = 1e-6
    fd = (distorted(n + h, k1, k2) - distorted(n - h, k1, k2)) / (2 * h)
    np.testing.assert_allclose(distortion_slope(n, k1, k2), fd, rtol=1e-8, atol=1e-10)


@pytest.mark.parametrize("k1, k2", LENSES)
def test_undistorted_inverts_distorted_on_arrays_and_floats(k1, k2):
    n = np.linspace(-0.3, 0.3, 61)
    back, converged = undistorted(distorted(n, k1, k2), k1, k2, 1e-12)
    assert converged
    assert np.abs(back - n).max() < 1e-12
    for x in n[::7]:
        u = float(project(x, 3000.0, 1023.5, k1, k2))
        m, ok = normalised(u, 3000.0, 1023.5, k1, k2)
        assert ok and abs(m - x) * 3000.0 < 1e-9


@settings(max_examples=200, deadline=None)
@given(
    n=st.floats(-0.35, 0.35),
    k1=st.floats(-0.3, 0.3),
    k2=st.floats(-0.05, 0.05),
    focal_px=st.floats(500.0, 8000.0),
    principal_px=st.floats(0.0, 4096.0),
)
def test_round_trip_and_the_compiled_twins(n, k1, k2, focal_px, principal_px):
    # within the distortion's monotonic range the pixel's coordinate comes back
    if float(distortion_slope(np.linspace(0.0, abs(n), 50), k1, k2).min()) <= 0.2:
        return
    u = project(n, focal_px, principal_px, k1, k2)
    m, ok = normalised(u, focal_px, principal_px, k1, k2)
    assert ok
    assert abs(m - n) * focal_px < 1e-8
    # the kernels' compiled forms are the same functions, bit for bit
    got = _compiled_forms(n, u, focal_px, principal_px, k1, k2)
    assert got == (distorted(n, k1, k2), distortion_slope(n, k1, k2), u, m, ok)


def test_camera_distortion_is_the_lens_model():
    cam = LineScanCamera(2048, 3000.0, 1023.5, 50000.0, None, k1=-0.05, k2=0.01)
    n = np.linspace(-0.3, 0.3, 31)
    u = cam.project_normalised(n)
    assert np.array_equal(cam.backproject(u), undistorted((u - cam.principal_px) / cam.focal_px, cam.k1, cam.k2, 1e-9 / cam.focal_px)[0])
    assert np.abs(cam.backproject(u) - n).max() * cam.focal_px < 1e-9
    assert np.array_equal(cam.distort_derivative(n), distortion_slope(n, cam.k1, cam.k2))


def test_normalised_coordinate_equals_the_camera_and_reports_divergence():
    cam = LineScanCamera(240, 3000.0, 119.5, 50000.0, None, k1=-0.4)
    u = np.linspace(-800.0, 1000.0, 41)
    ref = cam.backproject(u)
    got = np.array([normalised(x, cam.focal_px, cam.principal_px, cam.k1, cam.k2) for x in u], dtype=object)
    assert all(ok for _, ok in got)
    assert np.abs(np.array([n for n, _ in got]) - ref).max() * cam.focal_px < 1e-9
    assert normalised(5.0, 1.0, 0.0, 0.0, 0.0) == (5.0, True)
    # beyond the monotonic range of the distortion (n_d above its maximum 0.609)
    with pytest.raises(GeometryError):
        cam.undistort(np.array([0.7]))
    assert not normalised(0.7 * cam.focal_px + cam.principal_px, cam.focal_px, cam.principal_px, cam.k1, cam.k2)[1]