"""The command line: contract of geometry.md, one-line errors, demo."""

from __future__ import annotations

import json
import math

import pytest

from ballscan.cli.app import main

from .conftest import DATA


def run(capsys, *args):
    code = main([str(a) for a in args])
    out = capsys.readouterr()
    return code, out.out, out.err


def test_simulate_then_estimate_json(tmp_path, capsys):
    name = tmp_path / "serve"
    code, out, err = run(capsys, "simulate", "--preset", "tennis-serve", "--out", name, "--seed", "4")
    assert code == 0, err
    for suffix in (".png", ".camera.toml", ".truth.json"):
        assert (tmp_path / f"serve{suffix}").exists()
    truth = json.loads((tmp_path / "serve.truth.json").read_text())
    code, out, err = run(capsys, "estimate", f"{name}.png", "--camera", f"{name}.camera.toml", "--radius", truth["radius_m"], "--json", "--method", "paper", "--plot", tmp_path / "o.png")
    assert code == 0, err
    doc = json.loads(out)
    assert doc["image"].endswith("serve.png") and len(doc["balls"]) == 1
    ball = doc["balls"][0]
    for key in ("t_c_s", "position_m", "velocity_mps", "speed_mps", "method", "initial", "flags", "run_time_s", "undetermined"):
        assert key in ball
    assert ball["method"] == "paper"
    # the contract, not accuracy (the preset is a textured, shaded, noisy ball;
    # accuracy is tested in test_paper.py and test_estimate.py)
    assert abs(ball["velocity_mps"][0] - truth["velocity_mps"][0]) / truth["velocity_mps"][0] < 0.05
    assert (tmp_path / "o.png").stat().st_size > 1000


def test_simulate_contract_flags_clean(tmp_path, capsys):
    cam = DATA / "scenes" / "pub_tennis_serve.camera.toml"
    code, _, err = run(capsys, "simulate", "--camera", cam, "--radius", "0.0335", "--position", "0,0.01,3.0",
                       "--velocity", "30,1,-0.5", "--t-c", "0.0012", "--lines", "170", "--out", tmp_path / "s", "--noise", "none")
    assert code == 0, err
    truth = json.loads((tmp_path / "s.truth.json").read_text())
    assert truth["position_m"] == [0.0, 0.01, 3.0] and truth["t_c_s"] == 0.0012
    assert math.isclose(truth["speed_mps"], math.sqrt(30**2 + 1 + 0.25))
    code, out, err = run(capsys, "estimate", tmp_path / "s.png", "--camera", tmp_path / "s.camera.toml", "--radius", "0.0335")
    assert code == 0 and "ball 0" in out and "speed" in out


def test_estimate_no_ball_is_empty_list_exit_0(tmp_path, capsys):
    import numpy as np
    import imageio.v3 as iio

    iio.imwrite(tmp_path / "empty.png", np.full((50, 2048), 30, np.uint8))
    code, out, _ = run(capsys, "estimate", tmp_path / "empty.png", "--camera", DATA / "scenes" / "pub_tennis_serve.camera.toml", "--radius", "0.0335", "--json")
    assert code == 0 and json.loads(out)["balls"] == []


@pytest.mark.parametrize(
    "camera_text,needle",
    [
        ("width = 2048\nfocal_px = -1.0\nprincipal_px = 1023.5\nline_rate_hz = 1e4\n", "focal_px"),
        ("width = 2048\nfocal_px = nan\nprincipal_px = 1023.5\nline_rate_hz = 1e4\n", "focal_px"),
        ("width = 2048\nprincipal_px = 1023.5\nline_rate_hz = 1e4\n", "focal_px"),
        ("width = 2048\nfocal_px = 3000.0\nprincipal_px = 1023.5\nline_rate_hz = 1e4\n[pose]\nrotation = [[2,0,0],[0,1,0],[0,0,1]]\ntranslation = [0,0,0]\n", "pose.rotation"),
        ("width = \"x\"\nfocal_px = 3000.0\nprincipal_px = 1023.5\nline_rate_hz = 1e4\n", "width"),
    ],
)
def test_bad_camera_file_one_line_error(tmp_path, capsys, camera_text, needle):
    cam = tmp_path / "bad.camera.toml"
    cam.write_text(camera_text)
    code, out, err = run(capsys, "estimate", DATA / "scenes" / "pub_tennis_serve.png", "--camera", cam, "--radius", "0.0335")
    assert code != 0 and out == ""
    lines = err.strip().splitlines()
    assert len(lines) == 1 and "bad.camera.toml" in lines[0] and needle in lines[0]
    assert "Traceback" not in err


def test_bad_image_one_line_error(tmp_path, capsys):
    bad = tmp_path / "broken.png"
    bad.write_bytes(b"\x89PNG\r\n\x1a\n" + b"garbage" * 10)
    code, out, err = run(capsys, "estimate", bad, "--camera", DATA / "scenes" / "pub_tennis_serve.camera.toml", "--radius", "0.0335")
    assert code != 0 and len(err.strip().splitlines()) == 1 and "broken.png" in err
    code, out, err = run(capsys, "estimate", tmp_path / "missing.png", "--camera", DATA / "scenes" / "pub_tennis_serve.camera.toml", "--radius", "0.0335")
    assert code != 0 and "missing.png" in err and len(err.strip().splitlines()) == 1


def test_width_mismatch_and_bad_radius(tmp_path, capsys):
    cam = DATA / "scenes" / "pub_pingpong.camera.toml"  # 1024 px
    code, _, err = run(capsys, "estimate", DATA / "scenes" / "pub_tennis_serve.png", "--camera", cam, "--radius", "0.0335")
    assert code != 0 and "width" in err and len(err.strip().splitlines()) == 1
    code, _, err = run(capsys, "estimate", DATA / "scenes" / "pub_tennis_serve.png", "--camera", DATA / "scenes" / "pub_tennis_serve.camera.toml", "--radius", "-1")
    assert code != 0 and "radius" in err


def test_simulate_needs_camera_or_preset(tmp_path, capsys):
    code, _, err = run(capsys, "simulate", "--out", tmp_path / "x")
    assert code != 0 and "--camera" in err and len(err.strip().splitlines()) == 1
    code, _, err = run(capsys, "simulate", "--preset", "cricket", "--out", tmp_path / "x")
    assert code != 0 and "tennis-serve" in err


@pytest.mark.slow
def test_demo_runs(tmp_path, capsys):
    code, out, err = run(capsys, "demo", "--out", tmp_path)
    assert code == 0, err
    assert "paper" in out and "fit" in out and "error" in out
    assert (tmp_path / "tennis-serve.paper.png").exists() and (tmp_path / "tennis-serve.fit.png").exists()


def test_precision_prints_bounds(capsys):
    cam = DATA / "scenes" / "pub_tennis_serve.camera.toml"
    args = ("precision", "--camera", cam, "--radius", "0.0335", "--velocity", "44.5,3.9,-5.5", "--position", "0,-0.08,4.2")
    code, out, err = run(capsys, *args, "--edge-noise", "0.05")
    assert code == 0, err
    rows = {line.split()[0]: line.split() for line in out.splitlines()[2:]}
    sig = {k: float(v[3]) for k, v in rows.items()}
    # the weak axis: depth velocity far less certain than the crossing velocity
    assert sig["vz"] > 20 * sig["vx"] > 0
    code2, out2, _ = run(capsys, *args, "--edge-noise", "0.1")
    sig2 = {line.split()[0]: float(line.split()[3]) for line in out2.splitlines()[2:]}
    assert sig2["vx"] == pytest.approx(2 * sig["vx"], rel=2e-3)  # scales with the noise (4 printed digits)
    code, _, err = run(capsys, *args)
    assert code != 0 and "--edge-noise" in err
    # the pixel bound, with the columns' unknown gains (PRNU) widening it
    px = ("--pixel-noise", "2", "--contrast", "150")
    _, o0, _ = run(capsys, *args, *px)
    _, o1, _ = run(capsys, *args, *px, "--prnu", "0.02")
    s0 = {line.split()[0]: float(line.split()[3]) for line in o0.splitlines()[2:]}
    s1 = {line.split()[0]: float(line.split()[3]) for line in o1.splitlines()[2:]}
    assert "PRNU 0.02" in o1 and s1["z0"] > s0["z0"] and all(s1[k] >= s0[k] for k in s0)
    code, _, err = run(capsys, *args, *px, "--prnu", "1.5")
    assert code != 0 and "--prnu" in err
    code, _, err = run(capsys, *args, "--edge-noise", "0.05", "--prnu", "0.01")
    assert code != 0 and "--prnu" in err and "--pixel-noise" in err


def test_stream_simulate_and_watch_through_the_cli(tmp_path, capsys):
    raw = tmp_path / "s.raw"
    code, _, err = run(capsys, "simulate", "--stream", raw, "--preset", "table-tennis", "--lines", "6000", "--balls", "2", "--seed", "2")
    assert code == 0, err
    truth = [json.loads(line) for line in (tmp_path / "s.raw.truth.jsonl").read_text().splitlines()]
    code, out, err = run(capsys, "watch", raw, "--camera", f"{raw}.camera.toml", "--radius", truth[0]["radius_m"])
    assert code == 0, err
    found = [json.loads(line) for line in out.splitlines()]
    assert len(found) == len(truth) == 2
    for f, t in zip(found, truth):
        assert abs(f["t_c_s"] - t["t_c_s"]) < 1e-4 and f["source"]
    # a recipe file reaches the stream's estimates (the paper method's balls), and --rig refuses it by its name
    (tmp_path / "paper.toml").write_text('method = "paper"\n')
    code, out, err = run(capsys, "watch", raw, "--camera", f"{raw}.camera.toml", "--radius", truth[0]["radius_m"], "--recipe", tmp_path / "paper.toml")
    assert code == 0, err
    assert [json.loads(line)["method"] for line in out.splitlines()] == ["paper", "paper"]
    code, _, err = run(capsys, "watch", raw, raw, "--rig", f"{raw}.camera.toml", "--radius", truth[0]["radius_m"], "--recipe", tmp_path / "paper.toml")
    assert code == 2 and "watch --rig: --recipe does not apply" in err
    code, _, err = run(capsys, "watch", raw, raw, "--rig", f"{raw}.camera.toml", "--radius", truth[0]["radius_m"], "--shading")
    assert code == 2 and "watch --rig: --shading does not apply" in err  # given, even at its default


def test_experiment_commands_are_registered(capsys):
    code, out, _ = run(capsys, "experiment", "--help")
    assert code == 0 and "fig5" in out and "fig8" in out and "custom" in out


def test_simulate_refuses_a_ball_behind_the_camera(tmp_path, capsys):
    cam = DATA / "scenes" / "pub_tennis_serve.camera.toml"
    code, _, err = run(capsys, "simulate", "--camera", cam, "--radius", "0.0335", "--position", "0,0.01,-3.0",
                       "--velocity", "30,1,-0.5", "--t-c", "0.001", "--lines", "100", "--out", tmp_path / "b")
    assert code != 0 and "in front of the camera" in err and len(err.strip().splitlines()) == 1
    assert not (tmp_path / "b.png").exists()


def test_estimate_shading_switch(capsys):
    scene = DATA / "scenes" / "pub_pingpong"
    args = ("estimate", f"{scene}.png", "--camera", f"{scene}.camera.toml", "--radius", "0.02", "--json")
    code, out_on, err = run(capsys, *args)
    assert code == 0, err
    code, out_off, err = run(capsys, *args, "--no-shading")
    assert code == 0, err
    on, off = json.loads(out_on)["balls"][0], json.loads(out_off)["balls"][0]
    assert on["shading"]["light_dn"] is not None and off["shading"] is None
    assert off["time_shading_s"] == 0.0 and on["velocity_mps"] != off["velocity_mps"]


def test_estimate_pixels_switch(tmp_path, capsys):
    """--pixels: used on an untextured flat ball, refused (and said) on the textured pingpong scene."""
    cam = DATA / "scenes" / "pub_tennis_serve.camera.toml"
    code, _, err = run(capsys, "simulate", "--camera", cam, "--radius", "0.0335", "--position", "0,0.01,3.0", "--velocity", "30,0,2",
                       "--t-c", "0.0015", "--lines", "220", "--out", tmp_path / "s", "--noise", "none", "--flat")
    assert code == 0, err
    code, out, err = run(capsys, "estimate", tmp_path / "s.png", "--camera", cam, "--radius", "0.0335", "--json", "--pixels")
    assert code == 0, err
    ball = json.loads(out)["balls"][0]
    truth = json.loads((tmp_path / "s.truth.json").read_text())
    assert ball["pixels"] == "used"
    assert abs(ball["speed_mps"] - truth["speed_mps"]) / truth["speed_mps"] < 1e-3
    scene = DATA / "scenes" / "pub_pingpong"
    code, out, err = run(capsys, "estimate", f"{scene}.png", "--camera", f"{scene}.camera.toml", "--radius", "0.02", "--json", "--pixels")
    assert code == 0, err
    assert json.loads(out)["balls"][0]["pixels"] == "not_uniform"


def test_estimate_matched_switch(tmp_path, capsys):
    """Matched edges by default on a flat ball of an ideal sensor; --no-matched keeps the windows."""
    cam = DATA / "scenes" / "pub_tennis_serve.camera.toml"
    code, _, err = run(capsys, "simulate", "--camera", cam, "--radius", "0.0335", "--position", "0,0.01,3.0", "--velocity", "30,0,2",
                       "--t-c", "0.0015", "--lines", "220", "--out", tmp_path / "s", "--noise", "none", "--flat")
    assert code == 0, err
    args = ("estimate", tmp_path / "s.png", "--camera", cam, "--radius", "0.0335", "--json")
    code, on, err = run(capsys, *args)
    assert code == 0, err
    code, off, err = run(capsys, *args, "--no-matched")
    assert code == 0, err
    on, off = json.loads(on)["balls"][0], json.loads(off)["balls"][0]
    assert on["edges"] == "matched" and off["edges"] == "window"
    assert on["column_gain_sigma"] < 0.003


def test_the_program_exits_with_mains_status_its_objects_frozen_before_the_teardown():
    import subprocess
    import sys

    code = (
        "import gc, sys; from ballscan.cli import run; sys.argv = ['ballscan', '--version']\n"
        "try:\n    run()\nexcept SystemExit as e:\n    print(e.code, gc.get_freeze_count() > 0)"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout.split()
    assert out[-2:] == ["0", "True"]
    bad = subprocess.run([sys.executable, "-m", "ballscan", "estimate", "/no/such/image.png", "--radius", "0.03"], capture_output=True, text=True)
    assert bad.returncode == 2 and bad.stderr.startswith("ballscan: ")


def test_estimate_recipe_file_and_the_flags_over_it(tmp_path, capsys):
    """--recipe: the file's settings reach the estimator (and the result's 'recipe'); a flag given overrides the file; a result file re-runs its recipe."""
    scene = DATA / "scenes" / "pub_pingpong"
    args = ("estimate", f"{scene}.png", "--camera", f"{scene}.camera.toml", "--radius", "0.02", "--json")
    (tmp_path / "r.toml").write_text("shading = false\nrefined_background = true\n")
    code, out, err = run(capsys, *args, "--recipe", tmp_path / "r.toml")
    assert code == 0, err
    res = json.loads(out)
    assert res["recipe"] == {"shading": False, "refined_background": True}
    assert res["balls"][0]["shading"] is None and res["balls"][0]["background_refined"]
    code, out, err = run(capsys, *args, "--recipe", tmp_path / "r.toml", "--shading")
    assert code == 0, err
    assert json.loads(out)["recipe"] == {"refined_background": True}
    (tmp_path / "res.json").write_text(json.dumps(res))
    code, out, err = run(capsys, *args, "--recipe", tmp_path / "res.json")
    assert code == 0 and json.loads(out) == res | {"balls": json.loads(out)["balls"]}
    assert [b["velocity_mps"] for b in json.loads(out)["balls"]] == [b["velocity_mps"] for b in res["balls"]]
    (tmp_path / "bad.toml").write_text("shading = 'off'\n")
    code, out, err = run(capsys, *args, "--recipe", tmp_path / "bad.toml")
    assert code == 2 and out == "" and err.strip() == f"ballscan: error: {tmp_path / 'bad.toml'}: shading: expected True or False, got 'off'"
