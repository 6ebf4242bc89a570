"""Plausibility: a blob that is not a ball, a radius in the wrong unit, 8-bit data read as 16-bit are flagged, real balls are not."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from ballscan.lab.presets import PRESETS, get_preset
from ballscan.model.render import SensorNoise, render
from ballscan.pipeline.estimate import estimate_image
from ballscan.pipeline.plausibility import PlausibilityLimits, radius_problem
from ballscan.pipeline.recipe import Recipe
from ballscan.pipeline.report import format_table

PLAUSIBILITY_FLAGS = {"not_a_ball", "implausible_radius", "implausible_speed", "implausible_range", "wrong_bit_depth"}


def _shot(name="tennis-serve", noise=None, seed=1, motion=None):
    p = get_preset(name)
    shot = render(p.camera, [(motion or p.motion, p.appearance)], p.n_lines, seed=seed, **({} if noise is None else {"noise": noise}))
    return p, shot.image


@pytest.mark.parametrize("name", sorted(PRESETS))
def test_real_balls_are_not_flagged(name):
    p, image = _shot(name)
    report = estimate_image(image, p.camera, p.motion.radius_m)
    assert report.balls
    for b in report.balls:
        assert not PLAUSIBILITY_FLAGS & set(b.flags), (b.flags, b.extra.get("implausible"))


@pytest.mark.parametrize("noise", [SensorNoise.none(16), SensorNoise(bits=16, white_dn=0.9 * 65535), SensorNoise(bits=12, white_dn=0.9 * 4095)])
def test_real_16_and_12_bit_balls_are_not_taken_for_8_bit_pairs(noise):
    p, image = _shot("baseball-pitch", noise=noise, seed=4)
    assert image.dtype == np.uint16
    b = estimate_image(image, p.camera, p.motion.radius_m, bits=noise.bits).balls[0]
    assert "wrong_bit_depth" not in b.flags
    assert abs(b.speed_mps - p.motion.speed_mps) < 4 * b.speed_sigma_mps


def _square(size=60):
    rng = np.random.default_rng(0)
    img = 25.0 + rng.normal(0.0, 1.5, (150, 2048))
    img[40 : 40 + size, 900 : 900 + size] = 200.0
    return np.clip(np.round(img), 0, 255).astype(np.uint8)


@pytest.mark.parametrize("method", ["fit", "paper"])
def test_a_bright_square_is_not_a_ball(method):
    cam = get_preset("tennis-serve").camera
    report = estimate_image(_square(), cam, 0.0335, recipe=Recipe(method=method))
    (b,) = report.balls
    assert "not_a_ball" in b.flags
    assert "not_a_ball" in b.extra["implausible"]
    assert "UNRELIABLE" in format_table(report, cam)


def test_a_radius_typed_in_millimetres_is_flagged_with_a_hint():
    p, image = _shot()
    report = estimate_image(image, p.camera, 33.5)
    (b,) = report.balls
    assert {"implausible_radius", "implausible_speed", "implausible_range"} <= set(b.flags)
    assert "33.5 millimetres is 0.0335" in b.extra["implausible"]["implausible_radius"]
    table = format_table(report, p.camera)
    speed_line = next(line for line in table.splitlines() if line.strip().startswith("speed"))
    assert speed_line.endswith("(UNRELIABLE)")


@pytest.mark.parametrize(
    "radius,words",
    [(37.0, "37 millimetres is 0.037"), (3.35, "3.35 centimetres is 0.0335"), (1e6, "outside 1 mm to 0.5 m"), (1e-4, "outside 1 mm to 0.5 m")],
)
def test_radius_problem_names_the_unit(radius, words):
    assert words in radius_problem(radius)


@pytest.mark.parametrize("radius", [1e-3, 0.0335, 0.5])
def test_radius_problem_accepts_every_ball(radius):
    assert radius_problem(radius) is None


def test_eight_bit_lines_read_as_sixteen_bit_are_flagged():
    p, image = _shot()
    assert image.dtype == np.uint8
    pairs = np.ascontiguousarray(image).view("<u2")  # each value: two neighbouring 8-bit pixels
    cam = replace(p.camera, width=pairs.shape[1], principal_px=p.camera.principal_px / 2, focal_px=p.camera.focal_px / 2)
    report = estimate_image(pairs, cam, p.motion.radius_m)
    assert report.balls
    for b in report.balls:
        assert "wrong_bit_depth" in b.flags


def test_a_region_whose_numbers_fail_is_undetermined_with_its_reason(monkeypatch):
    import ballscan.pipeline.stages as stages

    def singular(*_a, **_k):
        raise np.linalg.LinAlgError("Eigenvalues did not converge")

    monkeypatch.setattr(stages, "normalised_box", singular)
    p, image = _shot()
    (b,) = estimate_image(image, p.camera, p.motion.radius_m).balls
    assert b.speed_mps is None and "degenerate" in b.flags
    assert "Eigenvalues did not converge" in b.extra["reason"]


@pytest.mark.parametrize("field", ["max_speed_mps", "max_range_m", "max_chi2_red", "max_fill"])
@pytest.mark.parametrize("value", [0.0, -1.0, float("nan"), float("inf")])
def test_limits_are_checked(field, value):
    with pytest.raises(ValueError, match=field):
        PlausibilityLimits(**{field: value})


def _run(capsys, *args):
    from ballscan.cli.app import main

    code = main([str(a) for a in args])
    out = capsys.readouterr()
    return code, out.out, out.err


def test_watch_with_dtype_uint16_on_8_bit_lines_flags_every_ball(tmp_path, capsys):
    import json

    raw = tmp_path / "s.raw"
    code, _, err = _run(capsys, "simulate", "--stream", raw, "--preset", "tennis-serve", "--lines", "8000", "--balls", "3", "--seed", "2")
    assert code == 0, err
    code, out, err = _run(capsys, "watch", raw, "--camera", f"{raw}.camera.toml", "--radius", "0.0335")
    assert code == 0, err
    assert all("wrong_bit_depth" not in json.loads(line)["flags"] for line in out.splitlines())
    code, out, err = _run(capsys, "watch", raw, "--camera", f"{raw}.camera.toml", "--radius", "0.0335", "--dtype", "uint16")
    found = [json.loads(line) for line in out.splitlines()]
    assert found
    for ball in found:
        assert "wrong_bit_depth" in ball["flags"], ball["flags"]


def test_watch_table_marks_a_wrong_bit_depth_ball_unreliable(tmp_path, capsys):
    raw = tmp_path / "s.raw"
    code, _, err = _run(capsys, "simulate", "--stream", raw, "--preset", "tennis-serve", "--lines", "8000", "--balls", "2", "--seed", "2")
    assert code == 0, err
    args = ("watch", raw, "--camera", f"{raw}.camera.toml", "--radius", "0.0335", "--format", "table")
    code, out, err = _run(capsys, *args)
    assert code == 0 and out.strip() and "UNRELIABLE" not in out
    code, out, err = _run(capsys, *args, "--dtype", "uint16")
    lines = [line for line in out.splitlines() if line.startswith("ball ")]
    assert lines and all(" m/s (UNRELIABLE) | " in line and "8-bit data read as 16-bit" in line for line in lines), out


@pytest.mark.parametrize("command", ["watch", "batch"])
def test_watch_and_batch_warn_of_a_radius_in_millimetres(tmp_path, capsys, command):
    raw = tmp_path / "s.raw"
    code, _, err = _run(capsys, "simulate", "--stream", raw, "--preset", "tennis-serve", "--lines", "4000", "--balls", "1", "--seed", "3")
    assert code == 0, err
    extra = ("--out", tmp_path / "o.csv") if command == "batch" else ()
    code, out, err = _run(capsys, command, raw, "--camera", f"{raw}.camera.toml", "--radius", "33.5", *extra)
    assert "ballscan: warning: --radius: radius 33.5 m is outside 1 mm to 0.5 m" in err
    code, out, err = _run(capsys, command, raw, "--camera", f"{raw}.camera.toml", "--radius", "1e308", *extra)
    assert code == 2 and "the unit is metres" in err and "Traceback" not in err


def test_estimate_radius_37_warns_of_the_unit_and_marks_the_table(capsys):
    from .conftest import DATA

    scene = DATA / "scenes" / "pub_tennis_serve"
    code, out, err = _run(capsys, "estimate", f"{scene}.png", "--camera", f"{scene}.camera.toml", "--radius", "37")
    assert code == 0
    assert err.strip() == "ballscan: warning: --radius: radius 37 m is outside 1 mm to 0.5 m, the range of any ball; the unit is metres: 37 millimetres is 0.037, 37 centimetres is 0.37"
    assert "UNRELIABLE (implausible_radius, implausible_speed, implausible_range)" in out


@pytest.mark.parametrize("radius", ["1e308", "1e6", "5e-324", "1e-9"])
def test_a_radius_the_arithmetic_cannot_take_is_refused_in_one_line(capsys, radius):
    from .conftest import DATA

    scene = DATA / "scenes" / "pub_pingpong"
    code, out, err = _run(capsys, "estimate", f"{scene}.png", "--camera", f"{scene}.camera.toml", "--radius", radius)
    assert code == 2 and out == ""
    assert err.count("\n") == 1 and "cannot be measured" in err and "the unit is metres" in err
