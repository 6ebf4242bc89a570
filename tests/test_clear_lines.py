"""Tests of ballscan.measure.clear_lines: the ball-free lines, the backdrop's profile and the lines' levels."""

from __future__ import annotations

import numpy as np

from ballscan.measure.clear_lines import clear_line_levels, column_noise, line_levels


def _backdrop(w: int, level: float = 150.0) -> np.ndarray:
    """A backdrop that varies across the sensor: a ramp and a wave, +-35 %, with 1 % column gains."""
    j = np.arange(w)
    rng = np.random.default_rng(11)
    return level * (1.0 + 0.25 * (j / w - 0.5) + 0.1 * np.sin(2 * np.pi * 1.5 * j / w)) * (1.0 + 0.01 * rng.normal(size=w))


def _scene(n, w, centre, radii, ball_dn, gains, sigma, seed):
    """Lines ``gains[i] * backdrop``, a shaded elliptic ball of about ``ball_dn`` (also lit by the lamp), Gaussian noise."""
    b = _backdrop(w)
    i, j = np.mgrid[:n, :w]
    r2 = ((i - centre[0]) / radii[0]) ** 2 + ((j - centre[1]) / radii[1]) ** 2
    inside = r2 <= 1.0
    img = gains[:, None] * b[None, :]
    shade = ball_dn * (0.7 + 0.3 * np.sqrt(np.clip(1.0 - r2, 0.0, 1.0)))
    img = np.where(inside, gains[:, None] * shade, img)
    rng = np.random.default_rng(seed)
    return img + rng.normal(0.0, sigma, img.shape), b, inside


def _levels(x):
    level = np.median(x, axis=1)
    return level, float(np.median(level))


def test_column_noise_ignores_flicker_and_the_ball():
    n, w = 300, 120
    gains = 1.0 + 0.3 * np.sin(2 * np.pi * 0.37 * np.arange(n))  # a lamp's flicker sampled line by line
    x, _, _ = _scene(n, w, (150, 60), (60, 12), 30.0, gains, 2.0, 1)
    level, ref = _levels(x)
    s = column_noise(x, level, ref, True)
    # away from the ball the per-line scaling leaves the noise (2 DN times ref/level)
    assert 1.6 < float(np.median(s)) < 2.6
    raw = np.std(np.diff(x[:, :20], axis=0)) / np.sqrt(2.0)
    assert raw > 10.0  # what consecutive lines' raw differences read as noise


def test_clear_lines_where_a_ball_covers_most_lines_of_its_columns():
    # a dark ball over 70 % of the lines of its columns on a backdrop that
    # varies across the sensor: its columns' medians read the ball
    n, w = 120, 130
    x, b, inside = _scene(n, w, (75, 34), (42, 5), 20.0, np.ones(n), 2.0, 2)
    level, ref = _levels(x)
    assert np.median(x[:, 34]) < 60.0
    cl = clear_line_levels(x, level, ref, np.full(w, 2.0), True)
    assert cl is not None
    assert inside[cl.lines].sum(axis=1).max() <= 1  # the backdrop's lines, or a ball's tip
    np.testing.assert_allclose(cl.level_dn * np.median(level[cl.lines]) / ref, b, atol=3.0)


def test_clear_lines_on_a_short_image_of_an_even_ball_cut_by_the_last_line():
    # more lines show the ball's wide middle (alike) than the backdrop: the
    # backdrop is told apart by the one run each line differs from it in
    n, w = 57, 103
    x, b, inside = _scene(n, w, (60, 46), (43, 9), 40.0, np.ones(n), 2.0, 3)
    level, ref = _levels(x)
    cl = clear_line_levels(x, level, ref, np.full(w, 2.0), True)
    assert cl is not None
    assert inside[cl.lines].sum(axis=1).max() <= 1
    np.testing.assert_allclose(cl.level_dn * np.median(level[cl.lines]) / ref, b, atol=3.0)


def test_clear_lines_none_without_a_ball_free_line():
    n, w = 40, 60
    rng = np.random.default_rng(4)
    x = 100.0 + 50.0 * rng.random((n, w))  # no two lines alike
    level, ref = _levels(x)
    assert clear_line_levels(x, level, ref, np.full(w, 1.0), True) is None


def test_line_levels_where_a_ball_covers_most_of_a_line():
    # the ball covers 80 % of its middle lines, the lamp flickers 25 %
    n, w = 110, 100
    gains = 1.0 + 0.25 * np.sin(2 * np.pi * 0.29 * np.arange(n))
    x, b, inside = _scene(n, w, (55, 50), (35, 40), 25.0, gains, 1.5, 5)
    first = np.median(x, axis=1) / np.median(b)
    wide = inside.sum(axis=1) > 0.6 * w
    assert np.all(np.abs(first[wide] - gains[wide]) > 0.2)  # the medians read the ball
    got = line_levels(x, b, np.full(w, 1.5), first, (0.75, 1.25), True)
    np.testing.assert_allclose(got, gains, atol=0.02)


def test_line_levels_offset_model():
    n, w = 80, 90
    offsets = 5.0 * np.sin(2 * np.pi * 0.21 * np.arange(n))
    rng = np.random.default_rng(6)
    prof = 10.0 + 2.0 * rng.random(w)
    x = prof[None, :] + offsets[:, None] + rng.normal(0.0, 1.0, (n, w))
    x[20:60, 10:80] = 200.0 + rng.normal(0.0, 1.0, (40, 70))  # a bright ball over most of 40 lines
    first = np.median(x, axis=1) - np.median(prof)
    got = line_levels(x, prof, np.full(w, 1.0), first, (-5.0, 5.0), False)
    np.testing.assert_allclose(got, offsets, atol=1.0)  # one noise sigma: a start for the first pass's 3-sigma window
