"""``ballscan simulate``: scenes with no ball in the image, non-finite numbers and oversized requests refused; outputs not written through symlinks."""

from __future__ import annotations

import json
import os

import pytest

from ballscan.cli.app import main

from .conftest import DATA

CAM = DATA / "scenes" / "pub_tennis_serve.camera.toml"
MOTION = ("--radius", "0.0335", "--position", "0,0.01,3.0", "--velocity", "30,1,-0.5", "--t-c", "0.0012", "--lines", "170")


def run(capsys, *args):
    code = main([str(a) for a in args])
    out = capsys.readouterr()
    return code, out.out, out.err


def _strict_json(text: str):
    def refuse(name):
        raise ValueError(f"non-finite number {name} in the JSON")

    return json.loads(text, parse_constant=refuse)


@pytest.mark.parametrize(
    "args,words",
    [
        (("--preset", "table-tennis", "--position", "0,-5,1.8"), "off the sensor"),
        (("--preset", "table-tennis", "--position", "0,5,1.8"), "off the sensor"),
        (("--preset", "table-tennis", "--t-c", "100"), "outside the image's lines"),
        (("--preset", "table-tennis", "--t-c", "-100"), "outside the image's lines"),
        (("--preset", "tennis-serve", "--lines", "2"), "stripe"),
        (("--preset", "table-tennis", "--lines", "3"), "stripe"),
        (("--preset", "table-tennis", "--radius", "1e-9"), "too small"),
        (("--preset", "table-tennis", "--radius", "1e-5"), "one DN"),
        (("--preset", "table-tennis", "--position", "0,0,1e4"), "too small, too far"),
        (("--preset", "table-tennis", "--background", "0", "--ball-level", "0"), "one DN"),
        (("--preset", "table-tennis", "--velocity", "1e-9,0,0"), "stripe"),
        (("--preset", "table-tennis", "--velocity", "0,0,0"), "--velocity: VX must be non-zero"),
        (("--preset", "table-tennis", "--velocity", "1e308,0,0"), "--velocity: a speed of 1e+308"),
        (("--preset", "table-tennis", "--velocity", "1e6,0,0"), "--velocity: a speed"),
        (("--preset", "table-tennis", "--position", "0,0,1e6"), "--position: a ball 100000 m or more away"),
        (("--preset", "table-tennis", "--radius", "2e6"), "--radius: a ball 100000 m or more wide"),
        (("--preset", "table-tennis", "--t-c", "1e300"), "--t-c: t_c = 1e+300 s is beyond any recording"),
        (("--preset", "tennis-serve", "--add-ball", "0.0335;0,-9,3;30,0,0;0.001"), "--add-ball 1: the ball never reaches the image"),
        (("--preset", "tennis-serve", "--bits", "0"), "--bits"),
        (("--preset", "tennis-serve", "--bits", "0", "--noise", "none"), "--bits"),
        (("--preset", "tennis-serve", "--bits", "7", "--noise", "none"), "--bits"),
        (("--preset", "tennis-serve", "--lines", "3000000"), "--stream"),
    ],
)
def test_a_scene_without_a_ball_or_beyond_reason_is_refused_and_nothing_written(tmp_path, capsys, args, words):
    code, _, err = run(capsys, "simulate", *args, "--out", tmp_path / "s")
    assert code == 2
    assert words in err and len(err.strip().splitlines()) == 1 and "Traceback" not in err
    assert os.listdir(tmp_path) == []


@pytest.mark.parametrize("args", [("--lines", "20"), ("--ball-level", "0.1"), ("--bits", "12")])
def test_scenes_with_a_ball_are_written_with_strict_json(tmp_path, capsys, args):
    code, _, err = run(capsys, "simulate", "--preset", "tennis-serve", *args, "--out", tmp_path / "s")
    assert code == 0, err
    truth = _strict_json((tmp_path / "s.truth.json").read_text())
    assert truth["radius_m"] == 0.0335


def test_lines_20_then_estimate_is_never_a_bare_number(tmp_path, capsys):
    assert run(capsys, "simulate", "--preset", "tennis-serve", "--lines", "20", "--out", tmp_path / "s")[0] == 0
    code, out, err = run(capsys, "estimate", tmp_path / "s.png", "--camera", tmp_path / "s.camera.toml", "--radius", "0.0335")
    assert code == 0, err
    for line in out.splitlines():
        if line.strip().startswith("speed"):
            assert "undetermined" in line or "UNRELIABLE" in line, out


@pytest.mark.parametrize(
    "args,words",
    [
        (("--radius", "nan"), "radius"),
        (("--radius", "inf"), "radius"),
        (("--radius", "-1"), "radius"),
        (("--lines", "3000000000"), "n_lines"),
        (("--balls", "-3"), "n_balls"),
        (("--balls", "100000"), "n_balls"),
    ],
)
def test_stream_values_refused_in_one_line(tmp_path, capsys, args, words):
    base = {"--radius": "0.0335", "--lines": "2000", "--balls": "2"}
    base.update(dict(zip(args[::2], args[1::2])))
    flat = [x for kv in base.items() for x in kv]
    code, _, err = run(capsys, "simulate", "--stream", tmp_path / "r.raw", "--preset", "tennis-serve", *flat)
    assert code == 2 and words in err and len(err.strip().splitlines()) == 1
    assert not (tmp_path / "r.raw").exists()


def test_a_symlinked_truth_is_not_overwritten_unless_forced(tmp_path, capsys):
    precious = tmp_path / "precious.json"
    precious.write_text('{"keep": true}')
    (tmp_path / "s.truth.json").symlink_to(precious)
    code, _, err = run(capsys, "simulate", "--camera", CAM, *MOTION, "--out", tmp_path / "s")
    assert code == 2 and "s.truth.json: is a symbolic link" in err
    assert precious.read_text() == '{"keep": true}'
    assert not (tmp_path / "s.png").exists()
    code, _, err = run(capsys, "simulate", "--camera", CAM, *MOTION, "--out", tmp_path / "s", "--force")
    assert code == 0, err
    assert (tmp_path / "s.truth.json").is_symlink() and _strict_json(precious.read_text())["radius_m"] == 0.0335


def test_a_symlinked_stream_output_is_refused(tmp_path, capsys):
    target = tmp_path / "log.txt"
    target.write_text("log")
    (tmp_path / "r.raw").symlink_to(target)
    code, _, err = run(capsys, "simulate", "--stream", tmp_path / "r.raw", "--preset", "tennis-serve", "--lines", "2000", "--balls", "2")
    assert code == 2 and "symbolic link" in err and target.read_text() == "log"


def test_estimate_plot_through_a_symlink_is_refused_before_the_work(tmp_path, capsys):
    scene = DATA / "scenes" / "pub_pingpong"
    target = tmp_path / "elsewhere.png"
    target.write_bytes(b"keep")
    (tmp_path / "o.png").symlink_to(target)
    args = ("estimate", f"{scene}.png", "--camera", f"{scene}.camera.toml", "--radius", "0.02", "--plot", tmp_path / "o.png")
    code, out, err = run(capsys, *args)
    assert code == 2 and "o.png: is a symbolic link" in err and out == ""
    assert target.read_bytes() == b"keep"
    code, _, err = run(capsys, *args, "--force")
    assert code == 0, err
    assert target.read_bytes()[:4] == b"\x89PNG"
