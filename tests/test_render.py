"""Tests of the synthetic renderer against the analytic silhouette (two independent models)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from ballscan.geometry.camera import LineScanCamera
from ballscan.errors import GeometryError
from ballscan.geometry.motion import BallMotion
from ballscan.lab.presets import PRESETS, get_preset
from ballscan.model.render import Appearance, RenderSettings, SensorNoise, _cap_lines, render, truth_dict, write_image
from ballscan.model.silhouette import silhouette, visible_line_count

BG = 0.1
LEVEL = 0.8


def _camera(k1: float = 0.0) -> LineScanCamera:
    # A wide field of view, so the ball sits where k1 = -0.05 moves it by about a pixel.
    return LineScanCamera(width=1024, focal_px=1500.0, principal_px=511.5, line_rate_hz=50000.0, k1=k1)


def _motion(kind: str, n_lines: int = 160, rate: float = 50000.0) -> BallMotion:
    v = {"perpendicular": (30.0, 0.0, 0.0), "oblique": (28.0, 6.0, -8.0)}[kind]
    return BallMotion(0.0335, 0.5 * n_lines / rate, (0.0, 0.45, 2.0), v)


def _area_edges(cov: np.ndarray, lines: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Left/right edges from partial coverage: middle pixel +- the summed coverage beside it."""
    j = np.arange(cov.shape[1])
    left, right = [], []
    for i in lines:
        row = cov[i]
        jm = int(round((row * j).sum() / row.sum()))
        left.append(jm + 0.5 - row[: jm + 1].sum())
        right.append(jm + 0.5 + row[jm + 1 :].sum())
    return np.array(left), np.array(right)


def _half_crossings(p: np.ndarray, lines: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Where each line's normalised profile (0 background, 1 ball) crosses 0.5, by linear interpolation."""
    left, right = [], []
    for i in lines:
        row = p[i]
        above = np.flatnonzero(row >= 0.5)
        k, m = above[0], above[-1]
        left.append(k - 1 + (0.5 - row[k - 1]) / (row[k] - row[k - 1]))
        right.append(m + (row[m] - 0.5) / (row[m] - row[m + 1]))
    return np.array(left), np.array(right)


def _full_lines(sil) -> np.ndarray:
    """Lines where the ball is seen in every (tilt, time) sample, minus two more at each end."""
    idx = np.flatnonzero(sil.present & (sil.presence > 1.0 - 1e-9))
    return idx[2:-2]


# ------------------------------------------------------------ edges vs silhouette


@pytest.mark.parametrize("k1", [0.0, -0.05])
@pytest.mark.parametrize("kind", ["perpendicular", "oblique"])
def test_edges_agree_with_averaged_silhouette(kind: str, k1: float) -> None:
    cam = _camera(k1)
    mo = _motion(kind)
    r = render(cam, (mo, Appearance.flat(LEVEL)), 160, background_level=BG, noise=None)
    sil = silhouette(cam, mo, r.t_lines_s, model="averaged")
    lines = _full_lines(sil)
    assert lines.size > 80

    left, right = _area_edges(r.coverage, lines)
    assert np.max(np.abs(left - sil.left_px[lines])) < 0.02
    assert np.max(np.abs(right - sil.right_px[lines])) < 0.02

    # Half-contrast crossings of the stored 16-bit image: biased by the linear
    # interpolation of a partly covered pixel (|bias| <= 0.09 px), RMS about 0.05 px.
    p = (r.image.astype(float) / 65535.0 - BG) / (LEVEL - BG)
    hl, hr = _half_crossings(p, lines)
    rms = math.sqrt(np.mean(np.concatenate([hl - sil.left_px[lines], hr - sil.right_px[lines]]) ** 2))
    assert rms < 0.07


def test_distortion_moves_the_ball() -> None:
    """Guards the edge test above: k1 must make a measurable difference there."""
    mo = _motion("perpendicular")
    a = render(_camera(0.0), (mo, Appearance.flat()), 160, noise=None).coverage
    b = render(_camera(-0.05), (mo, Appearance.flat()), 160, noise=None).coverage
    j = np.arange(a.shape[1])
    i = 80
    shift = (b[i] * j).sum() / b[i].sum() - (a[i] * j).sum() / a[i].sum()
    assert abs(shift) > 0.5


@pytest.mark.parametrize("kind", ["perpendicular", "oblique"])
def test_visible_line_count(kind: str) -> None:
    cam = _camera()
    mo = _motion(kind)
    r = render(cam, (mo, Appearance.flat()), 160, noise=None)
    seen = np.count_nonzero(r.coverage.max(axis=1) > 0)
    assert abs(seen - visible_line_count(cam, mo)) <= 1.0


def test_darker_ball_than_background() -> None:
    cam = _camera()
    mo = _motion("oblique")
    bright = render(cam, (mo, Appearance.flat(0.8)), 160, background_level=0.3, noise=None)
    dark = render(cam, (mo, Appearance.flat(0.05)), 160, background_level=0.9, noise=None)
    np.testing.assert_array_equal(bright.coverage, dark.coverage)
    inside = dark.coverage == 1.0
    assert inside.sum() > 1000
    np.testing.assert_allclose(dark.clean[inside], 0.05)
    np.testing.assert_allclose(dark.clean[dark.coverage == 0], 0.9)
    sil = silhouette(cam, mo, dark.t_lines_s)
    lines = _full_lines(sil)
    p = (dark.clean - 0.9) / (0.05 - 0.9)
    hl, hr = _half_crossings(p, lines)
    assert np.sqrt(np.mean((hl - sil.left_px[lines]) ** 2)) < 0.07


# ------------------------------------------------------------ noise and bit depth

NOISE12 = SensorNoise(bits=12, white_dn=3000.0, black_dn=100.0, read_dn=3.0, full_well_e=10000.0, prnu_sigma=0.01)


def test_seeded_determinism() -> None:
    cam = _camera()
    mo = _motion("oblique")
    a = render(cam, mo, 160, seed=5)
    b = render(cam, mo, 160, seed=5)
    c = render(cam, mo, 160, seed=6)
    np.testing.assert_array_equal(a.image, b.image)
    assert np.count_nonzero(a.image != c.image) > a.image.size // 4
    np.testing.assert_array_equal(a.clean, c.clean)  # the seed only drives the sensor noise


@pytest.mark.parametrize("Y", [0.3, 0.05])  # 3000 e (normal approximation of the shot noise) and 500 e (exact Poisson)
def test_noise_statistics(Y: float) -> None:
    cam = _camera()
    r = render(cam, [], 400, background_level=Y, noise=NOISE12, seed=1)
    img = r.image.astype(float)
    g = r.column_gain
    # Per column, over lines: shot + read + rounding noise (the column gain is fixed).
    expected_std = np.sqrt(NOISE12.read_dn**2 + NOISE12.white_dn**2 * Y * g / NOISE12.full_well_e + 1 / 12)
    ratio = img.std(axis=0, ddof=1) / expected_std
    assert abs(np.mean(ratio) - 1.0) < 0.15
    col_mean = img.mean(axis=0)
    np.testing.assert_allclose(np.mean(col_mean), NOISE12.black_dn + NOISE12.white_dn * Y, rtol=0.01)
    # Fixed-pattern gain: the spread of the column means across the sensor.
    prnu_dn = NOISE12.prnu_sigma * NOISE12.white_dn * Y
    assert abs(np.std(col_mean) / math.hypot(prnu_dn, np.mean(expected_std) / math.sqrt(400)) - 1.0) < 0.15
    assert abs(np.std(g) / NOISE12.prnu_sigma - 1.0) < 0.15


@pytest.mark.parametrize(
    ("noise", "dtype", "top"),
    [
        (SensorNoise(bits=8), np.uint8, 255),
        (SensorNoise(bits=12, white_dn=5000.0, black_dn=64.0, read_dn=4.0, full_well_e=20000.0), np.uint16, 4095),
        (SensorNoise(bits=16, white_dn=60000.0, black_dn=500.0, read_dn=10.0, full_well_e=30000.0), np.uint16, 65535),
        (SensorNoise.none(16), np.uint16, 65535),
    ],
)
def test_bit_depths(noise: SensorNoise, dtype: type, top: int) -> None:
    cam = _camera()
    r = render(cam, (_motion("perpendicular"), Appearance.flat(1.0)), 160, background_level=0.05, noise=noise, seed=2)
    assert r.image.dtype == dtype
    assert r.image.max() <= top
    if noise.bits == 12:
        assert r.image.max() == 4095  # white_dn > 4095: the ball saturates and is clipped
    assert r.image.min() >= 0
    if noise.is_noiseless:
        np.testing.assert_array_equal(r.image, np.rint(r.clean * 65535).astype(np.uint16))


def test_noise_none_string_is_clean_16_bit() -> None:
    r = render(_camera(), _motion("perpendicular"), 160, noise="none")
    assert r.image.dtype == np.uint16 and r.noise == SensorNoise.none()


# ------------------------------------------------------------ scenes


def test_two_balls_and_occlusion() -> None:
    cam = _camera()
    rate = cam.line_rate_hz
    near = BallMotion(0.0335, 80 / rate, (0.0, 0.10, 2.0), (30.0, 0.0, 0.0))
    far = BallMotion(0.0335, 80 / rate, (0.0, 0.20, 2.6), (30.0, 0.0, 0.0))  # behind `near`, overlapping its image edge
    apart = BallMotion(0.0335, 80 / rate, (0.0, -0.4, 2.0), (30.0, 0.0, 0.0))
    r = render(cam, [(near, Appearance.flat(0.9)), (far, Appearance.flat(0.3)), (apart, Appearance.flat(0.6))], 160, noise=None)
    row = r.clean[80]
    assert np.any(np.isclose(row, 0.6))  # the separate ball appears
    u_near = cam.project(0.10, 2.0)
    u_far_only = cam.project(0.20 + 0.02, 2.6)  # a point of the far ball outside the near one's image
    assert row[int(round(u_near))] == pytest.approx(0.9)
    assert row[int(round(u_far_only))] == pytest.approx(0.3)
    # Where both images overlap (near ball's right edge, far ball's left edge) the near one is seen.
    u_overlap = cam.project(0.10 + 0.03, 2.0)
    far_left = cam.project(0.20 - 0.0335, 2.6)
    assert far_left < u_overlap - 1
    assert row[int(round(u_overlap))] == pytest.approx(0.9)
    assert len(truth_dict(r.balls)["balls"]) == 3
    swapped = render(cam, [(far, Appearance.flat(0.3)), (near, Appearance.flat(0.9)), (apart, Appearance.flat(0.6))], 160, noise=None)
    np.testing.assert_array_equal(swapped.clean, r.clean)  # occlusion by distance, not by list order


def test_texture_changes_inside_not_edges() -> None:
    cam = _camera()
    mo = _motion("oblique")
    flat = render(cam, (mo, Appearance.flat(0.6)), 160, noise=None)
    tex = render(cam, (mo, Appearance(ball_level=0.6, texture="tennis", spin_rps=50.0, orientation_seed=4)), 160, noise=None)
    np.testing.assert_array_equal(flat.coverage, tex.coverage)
    inside = flat.coverage == 1.0
    assert np.count_nonzero(np.abs(tex.clean - flat.clean)[inside] > 0.05) > 100
    out = flat.coverage == 0.0
    np.testing.assert_array_equal(tex.clean[out], flat.clean[out])
    again = render(cam, (mo, Appearance(ball_level=0.6, texture="tennis", spin_rps=50.0, orientation_seed=4)), 160, noise=None)
    np.testing.assert_array_equal(again.clean, tex.clean)


def test_ball_partly_off_the_sensor_and_image() -> None:
    cam = _camera()
    # Centre at u ~ 2 (half the ball off pixel 0) and crossing at the first line.
    y0 = (2.0 - cam.principal_px) / cam.focal_px * 2.0
    mo = BallMotion(0.0335, 0.0, (0.0, y0, 2.0), (30.0, 0.0, 0.0))
    r = render(cam, mo, 120)
    assert r.coverage[0, 0] == 1.0
    assert r.coverage[:, 0].sum() > 20
    assert r.coverage[:, 200:].max() == 0.0


def test_camera_inside_ball_raises() -> None:
    mo = BallMotion(0.0335, 1e-3, (0.0, 0.0, 0.01), (30.0, 0.0, 0.0))
    with pytest.raises(GeometryError):
        render(_camera(), mo, 100)


def test_invalid_arguments() -> None:
    with pytest.raises(ValueError, match="bits"):
        SensorNoise(bits=10)
    with pytest.raises(ValueError, match="ball_level"):
        Appearance(ball_level=1.5)
    with pytest.raises(ValueError, match="texture"):
        Appearance(texture="golf")
    with pytest.raises(ValueError, match="n_lines"):
        render(_camera(), _motion("oblique"), 0)
    with pytest.raises(ValueError, match="noise"):
        render(_camera(), _motion("oblique"), 10, noise="loud")
    with pytest.raises(ValueError, match="samples_along"):
        RenderSettings(samples_along=0)


def test_write_image_round_trip(tmp_path) -> None:
    import imageio.v3 as iio

    r8 = render(_camera(), _motion("oblique"), 160, seed=3)
    r12 = render(_camera(), _motion("oblique"), 160, seed=3, noise=NOISE12)
    for name, r in (("a8.png", r8), ("a12.png", r12)):
        write_image(tmp_path / name, r.image)
        back = iio.imread(tmp_path / name)
        assert back.dtype == r.image.dtype
        np.testing.assert_array_equal(back, r.image)
    with pytest.raises(ValueError, match="image"):
        write_image(tmp_path / "bad.png", r8.clean)


# ------------------------------------------------------------ presets


@pytest.mark.parametrize("name", sorted(PRESETS))
def test_presets_fit_in_the_image(name: str) -> None:
    cam, mo, n_lines, app = get_preset(name)
    r = render(cam, (mo, app), n_lines, noise=None)
    rows = np.flatnonzero(r.coverage.max(axis=1) > 0)
    cols = np.flatnonzero(r.coverage.max(axis=0) > 0)
    margin_lines = 0.1 * visible_line_count(cam, mo)
    assert rows[0] >= margin_lines and rows[-1] <= n_lines - 1 - margin_lines
    assert cols[0] >= 0.1 * cam.width and cols[-1] <= 0.9 * cam.width
    assert r.coverage.max() == 1.0


def test_unknown_preset_lists_names() -> None:
    with pytest.raises(ValueError, match="tennis-serve"):
        get_preset("cricket")


# ------------------------------------------------------------ property test


@settings(max_examples=6, deadline=None, database=None)
@given(
    z=st.floats(1.0, 5.0),
    y_px=st.floats(-150.0, 150.0),
    radius=st.floats(0.015, 0.04),
    speed=st.floats(8.0, 60.0),
    psi_y=st.floats(-15.0, 15.0),
    psi_z=st.floats(-15.0, 15.0),
    exposure_frac=st.floats(0.2, 1.0),
    k1=st.floats(-0.08, 0.05),
)
def test_area_per_line_matches_silhouette(z, y_px, radius, speed, psi_y, psi_z, exposure_frac, k1) -> None:
    """Summed coverage per line equals silhouette's ``area_px``.

    Tolerance: the renderer integrates the line's chord width ``w(d)`` over
    the cut offset ``d = x_c(t) - s z_c`` with a midpoint grid of S tilts by
    T instants, whose 1-D star discrepancies are 1/(2S) and 1/(2T); by
    Koksma-Hlawka the error is at most about ``V (1/(2S) + 1/(2T))`` with
    ``V`` the variation of ``w`` over the line's range of ``d`` (large only
    on the first and last lines, where ``w`` has its square-root end, which
    therefore get the finer ``cap_across x cap_time`` grid).  Add 0.03 px
    for the along-sensor sampling of two edges (each about 0.01 px at worst,
    see the edge test).
    """
    rate = 40000.0
    cam = LineScanCamera(width=512, focal_px=2500.0, principal_px=255.5, line_rate_hz=rate, exposure_s=exposure_frac / rate, k1=k1)
    a, b = math.radians(psi_y), math.radians(psi_z)
    v = (speed * math.cos(a) * math.cos(b), speed * math.sin(a) * math.cos(b), speed * math.sin(b))
    n_lines = int(rate * (2 * radius + z / cam.focal_px) / v[0]) + 8
    mo = BallMotion(radius, 0.5 * n_lines / rate, (0.0, y_px * z / cam.focal_px, z), v)
    rs = RenderSettings()
    r = render(cam, (mo, Appearance.flat()), n_lines, noise=None, settings=rs)
    sil = silhouette(cam, mo, r.t_lines_s)
    assert not sil.degenerate
    area = r.coverage.sum(axis=1)
    expected = np.where(sil.present, sil.area_px, 0.0)

    # Variation of the chord width over each line's range of d, from the chord model at shifted times.
    half = cam.exposure * abs(v[0]) / 2 + z / (2 * cam.focal_px)
    widths = np.array(
        [np.nan_to_num(silhouette(cam, mo, r.t_lines_s + q * half / v[0], model="chord").area_px) for q in np.linspace(-1, 1, 9)]
    )
    variation = widths.max(axis=0) - widths.min(axis=0)
    cap = _cap_lines(cam, mo, r.t_lines_s)
    n_s = np.where(cap, rs.cap_across, rs.samples_across)
    n_t = np.where(cap, rs.cap_time, rs.samples_time)
    tol = 0.03 + variation * (1 / (2 * n_s) + 1 / (2 * n_t))
    bad = np.abs(area - expected) > tol
    assert not np.any(bad), f"lines {np.flatnonzero(bad)}: {area[bad]} vs {expected[bad]} (tol {tol[bad]})"
    assert abs(area.sum() - expected.sum()) < 0.002 * expected.sum()


@pytest.mark.parametrize("deg", [0.0, 30.0])
def test_cap_lines_match_the_continuous_exposure(deg: float) -> None:
    """The first and last lines' summed coverage, against the averaged silhouette.

    The analytic model integrates the exposure and the pixel's height with
    Gauss-Legendre nodes (it agrees with a 32 x 256 render to 0.001 px
    here).  Measured on these balls: at most 0.0104 px with the default
    16 x 16 cap grid, and 0.066 px with the other lines' 4 x 8 grid, which
    this test rejects.
    """
    cam = LineScanCamera(width=2048, focal_px=3000.0, principal_px=1023.5, line_rate_hz=50000.0)
    a = math.radians(deg)
    mo = BallMotion(0.0335, 0.002, (0.0, 0.01, 3.0), (30.0 * math.cos(a), 0.0, 30.0 * math.sin(a)))
    for rs, tol in ((RenderSettings(), 0.015), (RenderSettings(cap_across=4, cap_time=8), None)):
        r = render(cam, (mo, Appearance.flat()), 200, noise=None, settings=rs)
        sil = silhouette(cam, mo, r.t_lines_s)
        area = r.coverage.sum(axis=1)
        rows = np.flatnonzero(area > 0)
        ends = np.r_[rows[:4], rows[-4:]]
        err = np.abs(area[ends] - np.where(sil.present, sil.area_px, 0.0)[ends])
        if tol is not None:
            assert err.max() < tol, err
        else:
            assert err.max() > 0.03, err  # the coarse grid's bias, for contrast
