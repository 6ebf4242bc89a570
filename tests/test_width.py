"""Tests of the stream's width check (ballscan.stream.width): a pattern repeats at the true line length."""

from __future__ import annotations

import numpy as np
import pytest

from ballscan.stream.width import Z_DECIDE, WidthCheck


def _stream(true_width: int, n_lines: int, seed: int, pattern_dn: float = 0.25, noise_dn: float = 2.0, period: int | None = None) -> np.ndarray:
    """The samples of an 8-bit stream of ``true_width``-px lines: a fixed column pattern, a smooth profile, per-line flicker and noise."""
    rng = np.random.default_rng(seed)
    cols = np.arange(true_width)
    if period is None:
        pattern = pattern_dn * rng.standard_normal(true_width)
    else:
        pattern = pattern_dn * 4 * np.sign(np.sin(2 * np.pi * cols / period))  # a periodic scene (a net)
    profile = 30 + 8 * np.cos(np.pi * cols / true_width)  # vignetting
    flicker = 2.0 * rng.standard_normal((n_lines, 1))
    x = profile + pattern + flicker + noise_dn * rng.standard_normal((n_lines, true_width))
    return np.clip(np.rint(x), 0, 255).astype(np.uint8).reshape(-1)


def _judge(samples: np.ndarray, width: int, lines: int = 512, **kw) -> WidthCheck:
    n = samples.size // width
    x = samples[: n * width].reshape(n, width)
    wc = WidthCheck(width, **kw)
    for a in range(0, min(n, lines), 128):
        wc.add(x[a : a + 128], a, np.ones(x[a : a + 128].shape[0], bool))
    return wc


@pytest.mark.parametrize("seed", range(10))
def test_the_right_width_is_confirmed_never_refused(seed):
    wc = _judge(_stream(1024, 600, seed), 1024)
    assert wc.verdict.state == "confirmed" and wc.verdict.period_px == 1024 and wc.verdict.z > Z_DECIDE


@pytest.mark.parametrize("delta", [-64, -3, -1, 1, 2, 8])
def test_a_wrong_width_is_found_with_the_stream_s_own(delta):
    wc = _judge(_stream(1024 + delta, 600, 3), 1024)
    assert wc.sheared and wc.verdict.period_px == 1024 + delta
    assert wc.verdict.z_camera < wc.verdict.z / 4


def test_a_periodic_background_is_not_taken_for_a_shear():
    # the pattern repeats at W and at W +- its period: a tie, not a refusal
    for seed in range(5):
        wc = _judge(_stream(1024, 600, seed, period=8), 1024)
        assert wc.verdict.state == "confirmed"
    assert _judge(_stream(1023, 600, 0, period=8), 1024).sheared


def test_no_pattern_no_verdict():
    rng = np.random.default_rng(1)
    x = np.clip(np.rint(30 + 2.0 * rng.standard_normal(1024 * 2000)), 0, 255).astype(np.uint8)
    wc = _judge(x, 1024, lines=2000)
    assert wc.verdict.state == "unknown" and not wc.sheared
    # a smooth profile shows the lines' length by its jump from one line's end to the next's start
    assert _judge(_stream(1024, 2000, 1, pattern_dn=0.0), 1024, lines=2000).verdict.state == "confirmed"
    flat = np.full(1024 * 600, 30, np.uint8)  # a noise-free render
    assert _judge(flat, 1024).verdict.state == "unknown"


def test_lines_with_a_ball_are_left_out():
    x = _stream(1024, 600, 4).reshape(600, 1024).copy()
    # a bright slanted streak on lines 100-300 (a sheared-looking object) marked not clean
    for k in range(100, 300):
        x[k, 200 + k : 260 + k] = 250
    clean = np.ones(600, bool)
    clean[98:302] = False
    wc = WidthCheck(1024)
    wc.add(x, 0, clean)
    assert wc.verdict.state == "confirmed"


def test_sampling_after_the_start_and_a_later_shear():
    wc = WidthCheck(256, start_lines=256, every_blocks=2, block_lines=64, window_lines=256)
    good = _stream(256, 2048, 5).reshape(-1, 256)
    for a in range(0, 2048, 64):
        wc.add(good[a : a + 64], a, np.ones(64, bool))
    assert wc.verdict.state == "confirmed"
    assert wc.wants(0) and not wc.wants(64)  # one block in every_blocks
    bad = _stream(257, 4096, 6)[: 4096 * 256].reshape(-1, 256)
    for a in range(0, 4096, 64):
        wc.add(bad[a : a + 64], 2048 + a, np.ones(64, bool))
    assert wc.sheared and wc.verdict.period_px == 257


def test_lines_of_twice_the_width_read_as_two():
    for seed in range(5):
        assert _judge(_stream(1024, 600, seed), 1024).verdict.state == "confirmed"  # 2 W scores less than W
        wc = _judge(_stream(2048, 300, seed), 1024)
        assert wc.sheared and wc.verdict.period_px == 2048
