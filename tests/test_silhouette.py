"""Analytic silhouette against brute-force ray casting, like with like."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from ballscan.geometry.camera import LineScanCamera
from ballscan.geometry.motion import BallMotion
from ballscan.model.silhouette import LineStatus, silhouette, tangent_normalised, visible_line_count


def _ray_hits(centre: np.ndarray, R: float, s: float, n: np.ndarray) -> np.ndarray:
    """Whether the rays (s, n, 1) from the origin meet the sphere (discriminant test)."""
    d = np.stack([np.full_like(n, s), n, np.ones_like(n)], axis=-1)
    b = d @ centre
    cc = centre @ centre - R * R
    return (b * b - (d * d).sum(-1) * cc >= 0) & (b > 0)


def _brute_edges(centre: np.ndarray, R: float, s: float, n_guess: tuple[float, float]) -> tuple[float, float] | None:
    """Edges in n of the ball seen in the plane x = s z, by bisection on ray hits."""
    grid = np.linspace(n_guess[0], n_guess[1], 4001)
    hit = _ray_hits(centre, R, s, grid)
    if not hit.any():
        return None
    idx = np.flatnonzero(hit)
    out = []
    for a, b in ((grid[max(idx[0] - 1, 0)], grid[idx[0]]), (grid[idx[-1]], grid[min(idx[-1] + 1, grid.size - 1)])):
        inside_at_a = _ray_hits(centre, R, s, np.array([a]))[0]
        for _ in range(60):
            m = 0.5 * (a + b)
            if _ray_hits(centre, R, s, np.array([m]))[0] == inside_at_a:
                a = m
            else:
                b = m
        out.append(0.5 * (a + b))
    return out[0], out[1]


def _serve():
    cam = LineScanCamera(2048, 4200.0, 1023.5, 70000.0, 1.2e-5, k1=-0.05)
    m = BallMotion(0.0335, 0.0017, (0, -0.08, 4.2), (44.5, 3.9, -5.5))
    return cam, m, np.arange(240) / cam.line_rate_hz


def test_tangent_formula_against_geometry():
    n_lo, n_hi, ok = tangent_normalised(np.array([0.3]), np.array([4.0]), np.array([0.5]))
    assert ok[0]
    for n in (n_lo[0], n_hi[0]):
        # distance from the centre to the line y = n z equals the radius
        assert abs(0.3 - n * 4.0) / np.hypot(1, n) == pytest.approx(0.5, abs=1e-12)


def test_chord_model_against_bruteforce_plane():
    cam, m, t = _serve()
    sil = silhouette(cam, m, t, model="chord")
    lines = np.flatnonzero(sil.present)
    assert lines.size > 90
    for i in lines[:: max(1, lines.size // 15)].tolist() + [lines[0], lines[-1]]:
        c = m.centre(np.array([t[i]]))[0]
        e = _brute_edges(c, m.radius_m, 0.0, (-0.1, 0.1))
        assert e is not None
        u = cam.project_normalised(np.array(e))
        assert abs(u[0] - sil.left_px[i]) < 0.01 and abs(u[1] - sil.right_px[i]) < 0.01


@pytest.mark.slow
def test_averaged_model_against_bruteforce_slab_and_exposure():
    """Mean of the brute-force edges over a dense (exposure x pixel-height) grid."""
    cam, m, t = _serve()
    sil = silhouette(cam, m, t, model="averaged")
    lines = np.flatnonzero(sil.present)
    check = [lines[0], lines[1], lines[2], lines[lines.size // 2], lines[-3], lines[-2], lines[-1]]
    h = 1.0 / (2 * cam.focal_px)
    nt, ns = 24, 24
    for i in check:
        tt = t[i] + cam.exposure * ((np.arange(nt) + 0.5) / nt - 0.5)
        ss = h * (2 * (np.arange(ns) + 0.5) / ns - 1)
        lefts, rights, n_all = [], [], 0
        for tk in tt:
            c = m.centre(np.array([tk]))[0]
            for s in ss:
                n_all += 1
                e = _brute_edges(c, m.radius_m, s, (-0.1, 0.1))
                if e is None:
                    continue
                u = cam.project_normalised(np.array(e))
                lefts.append(u[0])
                rights.append(u[1])
        presence = len(lefts) / n_all
        assert presence == pytest.approx(sil.presence[i], abs=1.5 / ns)
        if sil.presence[i] == 1.0:
            assert abs(np.mean(lefts) - sil.left_px[i]) < 0.01
            assert abs(np.mean(rights) - sil.right_px[i]) < 0.01
        else:
            # partial lines: the grid's own sampling error dominates; still sub-0.05 px
            assert abs(np.mean(lefts) - sil.left_px[i]) < 0.05
            assert abs(np.mean(rights) - sil.right_px[i]) < 0.05


def test_averaged_sees_about_one_more_line_each_end():
    cam, m, t = _serve()
    chord = silhouette(cam, m, t, model="chord")
    avg = silhouette(cam, m, t, model="averaged")
    assert avg.first_line <= chord.first_line and avg.last_line >= chord.last_line
    n_avg = avg.last_line - avg.first_line + 1
    assert abs(n_avg - visible_line_count(cam, m)) <= 1.0
    # on central lines both models agree to a small fraction of a pixel
    mid = (avg.first_line + avg.last_line) // 2
    assert abs(avg.left_px[mid] - chord.left_px[mid]) < 0.01


def test_edges_inside_and_ordered():
    cam, m, t = _serve()
    sil = silhouette(cam, m, t)
    ok = sil.present
    assert np.all(sil.left_px[ok] < sil.right_px[ok])
    assert np.all(np.isnan(sil.left_px[~ok]))
    np.testing.assert_array_less(0, sil.area_px[ok])


def test_degenerate_cases_are_reported_not_numbers():
    cam = LineScanCamera(2048, 3000.0, 1023.5, 10000.0)
    t = np.arange(100) / cam.line_rate_hz
    # ball straddling the plane z = 0 beside the camera
    beside = BallMotion(0.1, 0.005, (0, 0.3, 0.05), (5.0, 0, 0))
    s = silhouette(cam, beside, t)
    assert s.degenerate and np.any(s.status == LineStatus.BEHIND)
    assert np.all(np.isnan(s.left_px[s.status == LineStatus.BEHIND]))
    # camera inside the ball
    inside = BallMotion(0.5, 0.005, (0, 0.0, 0.2), (5.0, 0, 0))
    s2 = silhouette(cam, inside, t, model="chord")
    assert np.any(s2.status == LineStatus.INSIDE) and s2.degenerate


def test_ball_partly_off_sensor_keeps_true_edges():
    cam = LineScanCamera(1024, 2000.0, 511.5, 20000.0)
    m = BallMotion(0.04, 0.002, (0, -0.78, 3.0), (20.0, 0, 0))
    s = silhouette(cam, m, np.arange(80) / cam.line_rate_hz)
    ok = s.present
    assert ok.any() and np.nanmin(s.left_px) < 0 < np.nanmax(s.right_px)


@settings(max_examples=40, deadline=None)
@given(
    y0=st.floats(-0.5, 0.5),
    z0=st.floats(1.0, 6.0),
    vx=st.floats(2.0, 60.0),
    vy=st.floats(-10.0, 10.0),
    vz=st.floats(-10.0, 10.0),
    radius=st.floats(0.015, 0.12),
)
def test_property_chord_edges_are_tangent(y0, z0, vx, vy, vz, radius):
    cam = LineScanCamera(4096, 4000.0, 2047.5, 50000.0)
    m = BallMotion(radius, 0.01, (0, y0, z0), (vx, vy, vz))
    t = np.linspace(0.01 - radius / vx, 0.01 + radius / vx, 50)
    s = silhouette(cam, m, t, model="chord")
    c = m.centre(t)
    for edge in (s.left_px, s.right_px):
        ok = ~np.isnan(edge)
        n = cam.backproject(edge[ok])
        cc = c[ok]
        rho = np.sqrt(radius**2 - cc[:, 0] ** 2)
        dist = np.abs(cc[:, 1] - n * cc[:, 2]) / np.hypot(1, n)
        np.testing.assert_allclose(dist, rho, rtol=1e-7, atol=1e-9)
    # the averaged model never sees fewer lines than the chord model
    a = silhouette(cam, m, t)
    assert a.present.sum() >= s.present.sum()
