"""What a person reads: the table in the world frame and in other units, the flags in words, CSV rows as the JSON says, the full covariance in the JSON."""

from __future__ import annotations

import csv
import io
import json
import math
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from ballscan.cli.app import main
from ballscan.geometry.camera import load_camera, save_camera
from ballscan.pipeline.estimate import estimate_image
from ballscan.pipeline.report import CSV_COLUMNS, FLAG_TEXT, UNITS, csv_row, format_table
from ballscan.pipeline.results import FLAGS
from ballscan.pipeline.recipe import Recipe
from ballscan.stream.batch import COLUMNS

SCENES = Path(__file__).resolve().parents[1] / "tests" / "data" / "scenes"
NAME = "pub_tennis_serve"
RADIUS = 0.0335
# world Z up, the camera looking horizontally along world +Y, its sensor (+y) pointing down
ROTATION = ((1.0, 0.0, 0.0), (0.0, 0.0, -1.0), (0.0, 1.0, 0.0))


@pytest.fixture(scope="module")
def posed(tmp_path_factory):
    cam = replace(load_camera(SCENES / f"{NAME}.camera.toml"), rotation=ROTATION, translation_m=(0.0, 1.5, 0.0))
    path = tmp_path_factory.mktemp("posed") / "posed.camera.toml"
    save_camera(cam, path)
    report = estimate_image(SCENES / f"{NAME}.png", cam, RADIUS)
    return cam, path, report


def test_every_flag_has_words():
    assert set(FLAG_TEXT) == set(FLAGS)


def test_the_table_shows_the_world_frame_and_the_launch_angles(posed):
    cam, _, report = posed
    text = format_table(report, cam)
    assert "world frame" in text and "world vel" in text and "launch       elevation" in text
    ball = report.balls[0]
    der = ball.derived(cam)
    assert f"elevation {der.elevation_deg:.2f} ± {der.elevation_sigma_deg:.2f} deg" in text
    # the camera's -y is world +Z: a ball moving towards the sensor's -y climbs
    assert math.copysign(1, der.elevation_deg) == -math.copysign(1, ball.velocity_mps[1])
    assert "world" not in format_table(report)  # no camera, no world frame


@pytest.mark.parametrize("units", ["m/s", "km/h", "mph"])
def test_the_table_converts_speeds_not_positions(posed, units):
    cam, _, report = posed
    b = report.balls[0]
    text = format_table(report, cam, units)
    assert f"speed        {b.speed_mps * UNITS[units]:.4f} ± {b.speed_sigma_mps * UNITS[units]:.4f} {units}" in text
    assert f"{b.position_m[2]:.5f}" in text
    assert UNITS["km/h"] == 3.6 and UNITS["mph"] == pytest.approx(2.2369362920544)
    with pytest.raises(ValueError, match="units"):
        format_table(report, cam, "furlong/fortnight")


def test_flags_are_in_words_and_unreliable_results_are_marked(posed):
    cam, _, report = posed
    b = replace(report.balls[0], flags=("cut_sensor_end", "not_converged"))
    text = format_table(replace(report, balls=(b,)), cam)
    assert "UNRELIABLE" in text.splitlines()[1]
    assert f"cut_sensor_end: {FLAG_TEXT['cut_sensor_end']}" in text


def test_the_json_holds_the_fits_full_covariance(posed):
    cam, _, report = posed
    b = report.balls[0]
    d = json.loads(report.to_json(cam))
    cov = d["balls"][0]["covariance"]
    assert cov["parameters"] == ["t_c_s", "y0_m", "z0_m", "vx_mps", "vy_mps", "vz_mps"]
    C = np.array(cov["matrix"])
    np.testing.assert_array_equal(C, b.covariance)
    np.testing.assert_allclose(np.sqrt(np.diag(C)), [b.t_c_sigma_s, *b.position_sigma_m[1:], *b.velocity_sigma_mps], rtol=1e-12)
    assert abs(C[0, 4]) > 0  # the cross-terms are there
    w = d["balls"][0]["world"]
    assert np.array(w["covariance"]["matrix"]).shape == (7, 7)
    assert d["ballscan_version"] and d["recipe"] == {}
    d2 = estimate_image(SCENES / f"{NAME}.png", cam, RADIUS, recipe=Recipe(shading=False)).to_dict(cam)
    assert d2["recipe"] == {"shading": False}


def test_csv_rows_say_what_the_json_says(posed):
    cam, _, report = posed
    assert COLUMNS == CSV_COLUMNS
    row = csv_row("x.png", 0, report.balls[0], cam)
    assert list(row) == list(CSV_COLUMNS)
    d = report.balls[0].to_dict(cam)
    assert float(row["speed_mps"]) == d["speed_mps"]
    assert float(row["vz_sigma_mps"]) == d["velocity_sigma_mps"][2]
    assert float(row["world_vz_mps"]) == d["world"]["velocity_mps"][2]
    assert float(row["elevation_sigma_deg"]) == d["world"]["elevation_sigma_deg"]
    assert float(row["psi_z_deg"]) == d["direction_deg"][1]


def test_estimate_csv_and_units_from_the_command_line(posed, capsys):
    _, path, report = posed
    png = str(SCENES / f"{NAME}.png")
    assert main(["estimate", png, "--camera", str(path), "--radius", str(RADIUS), "--csv"]) == 0
    rows = list(csv.DictReader(io.StringIO(capsys.readouterr().out)))
    assert len(rows) == len(report.balls) and rows[0]["world_vx_mps"] != ""
    assert main(["estimate", png, "--camera", str(path), "--radius", str(RADIUS), "--units", "mph"]) == 0
    assert " mph" in capsys.readouterr().out
    assert main(["estimate", png, "--camera", str(path), "--radius", str(RADIUS), "--units", "knots"]) != 0
    assert main(["estimate", png, "--camera", str(path), "--radius", str(RADIUS), "--csv", "--json"]) != 0
