"""Overlay plots: drawn on a given Axes without touching the backend, titled with speed, sigma and flags, in sensor and stream coordinates."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import matplotlib
import numpy as np
import pytest

from ballscan.geometry.camera import crop_camera, line_times, load_camera
from ballscan.measure.images import load_image
from ballscan.pipeline.estimate import estimate_image
from ballscan.pipeline.plot import ESTIMATE_STYLE, INITIAL_STYLE, plot_estimates, save_overlay

SCENES = Path(__file__).resolve().parents[1] / "tests" / "data" / "scenes"


@pytest.fixture(scope="module")
def scene():
    cam = load_camera(SCENES / "pub_tennis_serve.camera.toml")
    img = load_image(SCENES / "pub_tennis_serve.png")
    return cam, img, estimate_image(img, cam, 0.0335)


def test_a_given_axes_is_drawn_on_and_the_backend_left_alone(scene):
    from matplotlib.figure import Figure

    cam, img, report = scene
    backend = matplotlib.get_backend()
    fig = Figure()
    ax = fig.add_subplot()
    assert plot_estimates(img.data, cam, report, line_times(cam, img.n_lines), ax=ax) is fig
    assert matplotlib.get_backend() == backend
    colours = {line.get_color() for line in ax.lines}
    assert colours == {INITIAL_STYLE["color"], ESTIMATE_STYLE["color"]}


def test_the_title_gives_speed_sigma_and_flags(scene):
    cam, img, report = scene
    b = replace(report.balls[0], flags=("cut_sensor_end",))
    fig = plot_estimates(img.data, cam, replace(report, balls=(b,)), line_times(cam, img.n_lines), units="km/h")
    title = fig.axes[0].get_title()
    assert f"{b.speed_mps * 3.6:.2f} ± {b.speed_sigma_mps * 3.6:.2f} km/h" in title and "cut_sensor_end" in title


def test_a_crop_is_drawn_in_sensor_columns_and_stream_lines(scene, tmp_path):
    cam, img, report = scene
    cols = (800, 1100)
    crop = np.ascontiguousarray(img.data[:, cols[0] : cols[1]])
    ccam = crop_camera(cam, *cols)
    crep = estimate_image(crop, ccam, 0.0335, bits=8)
    t = line_times(ccam, crop.shape[0])
    fig = plot_estimates(crop, ccam, crep, t, first_column=cols[0], first_line=50_000)
    ax = fig.axes[0]
    lo, hi = ax.get_xlim()
    assert cols[0] - 0.5 <= lo < hi <= cols[1] - 0.5
    assert max(ax.get_ylim()) == pytest.approx(50_000 + crop.shape[0] - 0.5)
    est = [line for line in ax.lines if line.get_color() == ESTIMATE_STYLE["color"]][0]
    # the crop's contour lies where the whole image's does, in sensor columns
    full = plot_estimates(img.data, cam, report, line_times(cam, img.n_lines)).axes[0]
    ref = [line for line in full.lines if line.get_color() == ESTIMATE_STYLE["color"]][0]
    assert np.median(est.get_xdata()) == pytest.approx(np.median(ref.get_xdata()), abs=0.5)  # its own estimate, within a fraction of a pixel
    save_overlay(tmp_path / "o.png", crop, ccam, crep, t, first_column=cols[0])
    assert (tmp_path / "o.png").stat().st_size > 1000
